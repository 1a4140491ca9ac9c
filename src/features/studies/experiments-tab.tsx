"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useRouter } from "next/navigation";
import { useState, type FormEvent } from "react";
import { studyRoleMay, type StudyRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, Input, NativeSelect, Textarea } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Badge, EmptyState, Spinner } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";

export function ExperimentsTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const experiments = useQuery(trpc.experiments.list.queryOptions({ studyId }));
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.experiments.list.queryKey({ studyId }) });
  const publish = useMutation(trpc.versions.publish.mutationOptions({ onSuccess: refresh }));
  const edit = studyRoleMay(role, "experiment.edit");
  const router = useRouter();
  const rehearse = useMutation(trpc.trials.rehearse.mutationOptions({ onSuccess: (trial) => router.push(`/trials/${trial.id}`) }));
  const canRehearse = studyRoleMay(role, "trial.create");
  return (
    <div className="space-y-4">
      {edit && <NewExperimentDialog studyId={studyId} onCreated={refresh} />}
      {experiments.isPending && <Spinner />}
      <Problem error={experiments.error ?? publish.error ?? rehearse.error} />
      {experiments.data?.length === 0 && <EmptyState title="No experiments yet." />}
      {!!experiments.data?.length && (
        <Table>
          <thead>
            <tr>
              <Th>Experiment</Th>
              <Th>Robot</Th>
              <Th>Steps</Th>
              <Th>Published</Th>
              {(edit || canRehearse) && <Th className="text-right">Actions</Th>}
            </tr>
          </thead>
          <tbody>
            {experiments.data?.map((e) => (
              <tr key={e.id}>
                <Td>
                  <div className="font-medium">{e.name}</div>
                  <div className="text-xs text-slate-500">{e.description}</div>
                </Td>
                <Td>
                  <code className="text-xs">{e.robotPluginId}</code>
                </Td>
                <Td>{e.stepCount}</Td>
                <Td>{e.latestVersion ? <Badge tone="green">version {e.latestVersion}</Badge> : <Badge>draft only</Badge>}</Td>
                {(edit || canRehearse) && (
                  <Td className="space-x-2 text-right">
                    {canRehearse && (
                      <Button variant="ghost" size="sm" aria-label={`Rehearse ${e.name}`} disabled={rehearse.isPending} onClick={() => rehearse.mutate({ experimentId: e.id })}>
                        Rehearse
                      </Button>
                    )}
                    {edit && (
                      <Button variant="secondary" size="sm" aria-label={`Publish ${e.name}`} disabled={publish.isPending} onClick={() => publish.mutate({ experimentId: e.id })}>
                        Publish
                      </Button>
                    )}
                  </Td>
                )}
              </tr>
            ))}
          </tbody>
        </Table>
      )}
    </div>
  );
}

function NewExperimentDialog({ studyId, onCreated }: { studyId: string; onCreated: () => void }) {
  const trpc = useTRPC();
  const [open, setOpen] = useState(false);
  const [name, setName] = useState("");
  const [description, setDescription] = useState("");
  const [robot, setRobot] = useState("nao6-ros2");
  const robots = useQuery(trpc.plugins.list.queryOptions());
  const create = useMutation(
    trpc.experiments.create.mutationOptions({
      onSuccess: () => {
        setOpen(false);
        setName("");
        onCreated();
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate({ studyId, name, description, robotPluginId: robot });
  };
  return (
    <Dialog title="New experiment" open={open} onOpenChange={setOpen} trigger={<Button>New experiment</Button>}>
      <form onSubmit={submit} className="space-y-4">
        <Field label="Name" required error={fieldError(create.error, "name")}>
          {(p) => <Input {...p} value={name} onChange={(e) => setName(e.target.value)} autoFocus />}
        </Field>
        <Field label="Description">{(p) => <Textarea {...p} value={description} onChange={(e) => setDescription(e.target.value)} />}</Field>
        <Field label="Robot" required hint="Its actions appear in the designer; another robot can be chosen later.">
          {(p) => (
            <NativeSelect {...p} value={robot} onChange={(e) => setRobot(e.target.value)}>
              {robots.data?.robots.map((r) => (
                <option key={r.robotId} value={r.robotId}>
                  {r.name} ({r.version})
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        {create.error && !fieldError(create.error, "name") && <Problem error={create.error} />}
        <div className="flex justify-end">
          <Button type="submit" disabled={create.isPending}>
            Create experiment
          </Button>
        </div>
      </form>
    </Dialog>
  );
}
