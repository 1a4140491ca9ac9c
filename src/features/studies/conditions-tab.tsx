"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { strataCounts } from "@/core/studies/assignment";
import { ASSIGNMENT_STRATEGIES, type StudySettings } from "@/core/studies/settings";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Card, EmptyState } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";

const STRATEGY_HELP: Record<(typeof ASSIGNMENT_STRATEGIES)[number], string> = {
  fixed: "You choose each participant's condition.",
  random: "Each participant gets a random condition.",
  balanced: "Randomised in blocks, so the groups never differ by more than one block.",
  stratified: "Balanced blocks kept for each answer to a demographic question, so every group is spread evenly.",
  counterbalanced: "Within-subject: everyone gets every condition, in Latin-square orders.",
};

type Strategy = StudySettings["assignment"]["strategy"];

export function ConditionsTab({
  studyId,
  role,
  settings,
}: {
  studyId: string;
  role: StudyRole;
  settings: StudySettings;
}) {
  const { assignment } = settings;
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const list = useQuery(trpc.conditions.list.queryOptions({ studyId }));
  const experiments = useQuery(trpc.experiments.list.queryOptions({ studyId }));
  const edit = studyRoleMay(role, "experiment.edit");
  const [name, setName] = useState("");
  const [experimentId, setExperimentId] = useState("");
  const [strategy, setStrategy] = useState(assignment.strategy);
  const [perCondition, setPerCondition] = useState(assignment.perCondition);
  // Empty: the server makes one. A team that preregistered its seed types it here, before the first assignment.
  const [seed, setSeed] = useState("");
  // Only questions with a fixed set of answers can make strata (see settingsProblems).
  const questions = settings.demographics.filter((f) => f.type === "choice");
  const [stratifyBy, setStratifyBy] = useState(assignment.stratifyBy ?? questions[0]?.key ?? "");
  const blocks = strategy === "balanced" || strategy === "stratified";
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.conditions.list.queryKey({ studyId }) });
  const create = useMutation(trpc.conditions.create.mutationOptions({ onSuccess: () => (setName(""), refresh()) }));
  const update = useMutation(
    trpc.studies.update.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.studies.get.queryKey({ studyId }) }),
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate({ studyId, name, experimentId });
  };
  return (
    <div className="space-y-6">
      {studyRoleMay(role, "study.update") && (
        <Card className="flex flex-wrap items-end gap-3 p-5">
          <div className="w-64">
            <Field label="Assignment strategy" hint={STRATEGY_HELP[strategy]}>
              {(p) => (
                <NativeSelect {...p} value={strategy} onChange={(e) => setStrategy(e.target.value as Strategy)}>
                  {ASSIGNMENT_STRATEGIES.map((s) => (
                    <option key={s}>{s}</option>
                  ))}
                </NativeSelect>
              )}
            </Field>
          </div>
          {strategy === "stratified" && (
            <div className="w-64">
              <Field
                label="Stratify by"
                hint={
                  questions.length
                    ? "Each answer is balanced on its own."
                    : "Add a choice question under Overview first."
                }
              >
                {(p) => (
                  <NativeSelect {...p} value={stratifyBy} onChange={(e) => setStratifyBy(e.target.value)}>
                    {questions.map((f) => (
                      <option key={f.key} value={f.key}>
                        {f.label}
                      </option>
                    ))}
                  </NativeSelect>
                )}
              </Field>
            </div>
          )}
          {blocks && (
            <div className="w-40">
              <Field label="Each condition per block">
                {(p) => (
                  <Input
                    {...p}
                    type="number"
                    min={1}
                    max={20}
                    value={perCondition}
                    onChange={(e) => setPerCondition(Number(e.target.value))}
                  />
                )}
              </Field>
            </div>
          )}
          <div className="w-56">
            <Field
              label="Seed (optional)"
              hint="Your own, before the first assignment; empty for a new one."
              error={fieldError(update.error, "settings.assignment.seed")}
            >
              {(p) => <Input {...p} value={seed} onChange={(e) => setSeed(e.target.value)} />}
            </Field>
          </div>
          <Button
            className="mb-5"
            disabled={update.isPending || (strategy === "stratified" && !stratifyBy)}
            onClick={() =>
              update.mutate({
                studyId,
                settings: {
                  assignment: {
                    strategy,
                    perCondition: blocks ? perCondition : 1,
                    ...(strategy === "stratified" ? { stratifyBy } : {}),
                    ...(seed.trim() ? { seed } : {}),
                  },
                },
              })
            }
          >
            Use this strategy
          </Button>
          <Problem error={update.error} />
          {assignment.seed && (
            <p className="mb-5 text-xs text-slate-500">
              Seed for the audit: <code>{assignment.seed}</code>
            </p>
          )}
        </Card>
      )}
      {edit && (
        <Card className="p-5">
          <h2 className="mb-3 font-semibold">Add a condition</h2>
          <form onSubmit={submit} className="flex flex-wrap items-end gap-3">
            <div className="w-64">
              <Field label="Condition name" required error={fieldError(create.error, "name")}>
                {(p) => (
                  <Input
                    {...p}
                    value={name}
                    onChange={(e) => setName(e.target.value)}
                    placeholder="NAO with gestures"
                  />
                )}
              </Field>
            </div>
            <div className="w-64">
              <Field label="Runs experiment" required>
                {(p) => (
                  <NativeSelect {...p} value={experimentId} onChange={(e) => setExperimentId(e.target.value)}>
                    <option value="">Choose…</option>
                    {experiments.data?.map((x) => (
                      <option key={x.id} value={x.id}>
                        {x.name} ({x.robotId})
                      </option>
                    ))}
                  </NativeSelect>
                )}
              </Field>
            </div>
            <Button type="submit" className="mb-5" disabled={!experimentId || create.isPending}>
              Add condition
            </Button>
          </form>
          {create.error && !fieldError(create.error, "name") && <Problem error={create.error} />}
        </Card>
      )}
      {assignment.strategy === "stratified" && list.data && (
        <StrataTable studyId={studyId} conditions={list.data.map((c) => ({ id: c.id, name: c.name }))} />
      )}
      <ListView
        query={list}
        problem={update.error}
        empty={<EmptyState title="No conditions yet.">A study with one condition needs none.</EmptyState>}
        columns={
          <>
            <Th>Condition</Th>
            <Th>Experiment</Th>
            <Th>Robot</Th>
            <Th>Participants</Th>
          </>
        }
        row={(c) => (
          <tr key={c.id}>
            <Td className="font-medium">{c.name}</Td>
            <Td>{c.experimentName}</Td>
            <Td>
              <code className="text-xs">{c.robotId}</code>
            </Td>
            <Td>{c.participantCount}</Td>
          </tr>
        )}
      />
    </div>
  );
}

/** Participants per stratum and condition: the balance the strategy promises, there to check. */
function StrataTable({ studyId, conditions }: { studyId: string; conditions: Array<{ id: string; name: string }> }) {
  const trpc = useTRPC();
  const participants = useQuery(trpc.participants.list.queryOptions({ studyId }));
  const rows = strataCounts((participants.data ?? []).map((p) => ({ stratum: p.stratum, condition: p.conditionId })));
  if (!rows.length) return null;
  return (
    <Card className="overflow-x-auto p-5">
      <h2 className="mb-3 font-semibold">Participants per stratum</h2>
      <table className="text-sm">
        <thead>
          <tr>
            <Th>Stratum</Th>
            {conditions.map((c) => (
              <Th key={c.id}>{c.name}</Th>
            ))}
          </tr>
        </thead>
        <tbody>
          {rows.map((r) => (
            <tr key={r.stratum}>
              <Td className="font-medium">{r.stratum}</Td>
              {conditions.map((c) => (
                <Td key={c.id}>{r.counts[c.id] ?? 0}</Td>
              ))}
            </tr>
          ))}
        </tbody>
      </table>
    </Card>
  );
}
