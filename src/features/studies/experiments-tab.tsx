"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import Link from "next/link";
import { useRouter } from "next/navigation";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, Input, NativeSelect, Textarea } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Badge, EmptyState, Spinner } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";
import { DuplicateExperimentDialog } from "./duplicate-experiment-dialog";
import { RehearseButton } from "./rehearse-button";

export function ExperimentsTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const experiments = useQuery(trpc.experiments.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.experiments.list.queryKey({ studyId }) });
  const publish = useMutation(trpc.versions.publish.mutationOptions({ onSuccess: refresh }));
  const edit = studyRoleMay(role, "experiment.edit");
  const router = useRouter();
  const rehearse = useMutation(
    trpc.trials.rehearse.mutationOptions({ onSuccess: (trial) => router.push(`/trials/${trial.id}`) }),
  );
  const canRehearse = studyRoleMay(role, "trial.create");
  // (A wizard blinded to conditions has no Experiments tab.)
  const conditions = useQuery({ ...trpc.conditions.list.queryOptions({ studyId }), enabled: canRehearse });
  const conditionsOf = (experimentId: string) =>
    (conditions.data ?? []).filter((c) => c.experimentId === experimentId).map((c) => c.name);
  return (
    <div className="space-y-4">
      {edit && (
        <div className="flex gap-2">
          <NewExperimentDialog studyId={studyId} onCreated={(id) => router.push(`/experiments/${id}`)} />
          <ImportExperimentDialog studyId={studyId} onImported={(id) => router.push(`/experiments/${id}`)} />
        </div>
      )}
      <ListView
        query={experiments}
        problem={publish.error ?? rehearse.error}
        empty={<EmptyState title="No experiments yet." />}
        columns={
          <>
            <Th>Experiment</Th>
            <Th>Robot</Th>
            <Th>Steps</Th>
            <Th>Published</Th>
            <Th className="text-right">Actions</Th>
          </>
        }
        row={(e) => (
          <tr key={e.id}>
            <Td>
              <Link href={`/experiments/${e.id}`} className="font-medium text-brand-700 hover:underline">
                {e.name}
              </Link>
              <div className="text-xs text-slate-500">{e.description}</div>
            </Td>
            <Td>
              <code className="text-xs">{e.robotId}</code>
            </Td>
            <Td>{e.stepCount}</Td>
            <Td>
              {e.latestVersion ? <Badge tone="green">version {e.latestVersion}</Badge> : <Badge>draft only</Badge>}
            </Td>
            <Td className="space-x-2 text-right">
              <Button variant="ghost" size="sm" asChild>
                <Link href={`/experiments/${e.id}`} aria-label={`${edit ? "Design" : "Open"} ${e.name}`}>
                  {edit ? "Design" : "Open"}
                </Link>
              </Button>
              {canRehearse && (
                <RehearseButton
                  experiment={e}
                  conditions={conditionsOf(e.id)}
                  pending={rehearse.isPending}
                  onRehearse={(input) => rehearse.mutate(input)}
                />
              )}
              {edit && <DuplicateExperimentDialog studyId={studyId} experiment={e} />}
              {edit && (
                <Button
                  variant="secondary"
                  size="sm"
                  aria-label={`Publish ${e.name}`}
                  disabled={publish.isPending}
                  onClick={() => publish.mutate({ experimentId: e.id })}
                >
                  Publish
                </Button>
              )}
            </Td>
          </tr>
        )}
      />
    </div>
  );
}

function NewExperimentDialog({ studyId, onCreated }: { studyId: string; onCreated: (experimentId: string) => void }) {
  const trpc = useTRPC();
  const [open, setOpen] = useState(false);
  const [name, setName] = useState("");
  const [description, setDescription] = useState("");
  const [robot, setRobot] = useState("nao6-ros2");
  const robots = useQuery(trpc.plugins.list.queryOptions());
  const create = useMutation(
    trpc.experiments.create.mutationOptions({
      onSuccess: (row) => {
        setOpen(false);
        setName("");
        onCreated(row.id);
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate({ studyId, name, description, robotId: robot });
  };
  return (
    <Dialog title="New experiment" open={open} onOpenChange={setOpen} trigger={<Button>New experiment</Button>}>
      <form onSubmit={submit} className="space-y-4">
        <Field label="Name" required error={fieldError(create.error, "name")}>
          {(p) => <Input {...p} value={name} onChange={(e) => setName(e.target.value)} autoFocus />}
        </Field>
        <Field label="Description">
          {(p) => <Textarea {...p} value={description} onChange={(e) => setDescription(e.target.value)} />}
        </Field>
        <Field label="Robot" required hint="Its actions appear in the designer; another robot can be chosen later.">
          {(p) => (
            <NativeSelect {...p} value={robot} onChange={(e) => setRobot(e.target.value)}>
              {/* One entry per robot; the designer chooses among several sources' documents of it. */}
              {robots.data?.robots
                .filter((r) => r.isDefault)
                .map((r) => (
                  <option key={r.robotId} value={r.robotId}>
                    {r.name} ({r.version})
                  </option>
                ))}
            </NativeSelect>
          )}
        </Field>
        {create.error && !fieldError(create.error, "name") && <Problem error={create.error} />}
        <div className="flex justify-end">
          {/* Until the robots arrive the required select is empty, and the browser would silently refuse to send. */}
          <Button type="submit" disabled={create.isPending || !robots.data}>
            {robots.data ? "Create experiment" : "Loading robots…"}
          </Button>
        </div>
      </form>
    </Dialog>
  );
}

/** An experiment file exported from this or another lab's HRIStudio. */
function ImportExperimentDialog({
  studyId,
  onImported,
}: {
  studyId: string;
  onImported: (experimentId: string) => void;
}) {
  const trpc = useTRPC();
  const [open, setOpen] = useState(false);
  const [fileProblem, setFileProblem] = useState<string | null>(null);
  const importFile = useMutation(
    trpc.experiments.importFile.mutationOptions({ onSuccess: (design) => onImported(design.id) }),
  );
  const choose = async (file: File | undefined) => {
    setFileProblem(null);
    if (!file) return;
    if (file.size > 2_000_000)
      return setFileProblem(
        `“${file.name}” is ${(file.size / 1e6).toFixed(1)} MB; an experiment file must be smaller than 2 MB.`,
      );
    importFile.mutate({ studyId, text: await file.text() });
  };
  return (
    <Dialog
      title="Import an experiment"
      description="From a file exported by HRIStudio (.hristudio-experiment.json)."
      open={open}
      onOpenChange={setOpen}
      trigger={<Button variant="secondary">Import file</Button>}
    >
      <div className="space-y-3">
        <Field label="Experiment file">
          {(p) => (
            <input
              {...p}
              type="file"
              accept=".json,application/json"
              className="text-sm"
              onChange={(e) => void choose(e.target.files?.[0])}
            />
          )}
        </Field>
        {importFile.isPending && <Spinner label="Importing…" />}
        <Problem error={fileProblem ? { message: fileProblem } : importFile.error} />
      </div>
    </Dialog>
  );
}
