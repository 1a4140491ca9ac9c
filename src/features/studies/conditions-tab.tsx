"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { ASSIGNMENT_STRATEGIES } from "@/core/studies/settings";
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
  counterbalanced: "Within-subject: everyone gets every condition, in Latin-square orders.",
};

type Assignment = { strategy: (typeof ASSIGNMENT_STRATEGIES)[number]; perCondition: number; seed?: string };

export function ConditionsTab({
  studyId,
  role,
  assignment,
}: {
  studyId: string;
  role: StudyRole;
  assignment: Assignment;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const list = useQuery(trpc.conditions.list.queryOptions({ studyId }));
  const experiments = useQuery(trpc.experiments.list.queryOptions({ studyId }));
  const edit = studyRoleMay(role, "experiment.edit");
  const [name, setName] = useState("");
  const [experimentId, setExperimentId] = useState("");
  const [strategy, setStrategy] = useState(assignment.strategy);
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
                <NativeSelect
                  {...p}
                  value={strategy}
                  onChange={(e) => setStrategy(e.target.value as Assignment["strategy"])}
                >
                  {ASSIGNMENT_STRATEGIES.map((s) => (
                    <option key={s}>{s}</option>
                  ))}
                </NativeSelect>
              )}
            </Field>
          </div>
          <Button
            className="mb-5"
            disabled={update.isPending}
            onClick={() => update.mutate({ studyId, settings: { assignment: { strategy, perCondition: 1 } } })}
          >
            Use this strategy
          </Button>
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
