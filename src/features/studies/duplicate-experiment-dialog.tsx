"use client";
import { useMutation, useQuery } from "@tanstack/react-query";
import { useRouter } from "next/navigation";
import { useState, type FormEvent } from "react";
import { studyRoleMay } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";

/** A copy of an experiment's design, in this study or another one the caller designs in. */
export function DuplicateExperimentDialog({
  studyId,
  experiment,
}: {
  studyId: string;
  experiment: { id: string; name: string };
}) {
  const trpc = useTRPC();
  const router = useRouter();
  const [open, setOpen] = useState(false);
  const [into, setInto] = useState("");
  // Only studies I design in are offered; the server checks again.
  const studies = useQuery({ ...trpc.studies.mine.queryOptions(), enabled: open });
  const targets = studies.data?.filter((s) => s.id !== studyId && studyRoleMay(s.role, "experiment.edit")) ?? [];
  const duplicate = useMutation(
    trpc.experiments.duplicate.mutationOptions({ onSuccess: (copy) => router.push(`/experiments/${copy.id}`) }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    duplicate.mutate({ experimentId: experiment.id, intoStudyId: into || undefined });
  };
  return (
    <Dialog
      title={`Duplicate ${experiment.name}`}
      description="The design only: its published versions, trials and data stay where they are."
      open={open}
      onOpenChange={setOpen}
      trigger={
        <Button variant="ghost" size="sm" aria-label={`Duplicate ${experiment.name}`}>
          Duplicate
        </Button>
      }
    >
      <form onSubmit={submit} className="space-y-4">
        <Field label="Copy into" hint="In this study the copy is named “… (copy)”; in another study it keeps its name.">
          {(p) => (
            <NativeSelect {...p} value={into} onChange={(e) => setInto(e.target.value)}>
              <option value="">This study</option>
              {targets.map((s) => (
                <option key={s.id} value={s.id}>
                  {s.title}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <Problem error={duplicate.error ?? studies.error} />
        <div className="flex justify-end gap-2">
          <Button variant="secondary" onClick={() => setOpen(false)}>
            Cancel
          </Button>
          <Button type="submit" disabled={duplicate.isPending}>
            Duplicate
          </Button>
        </div>
      </form>
    </Dialog>
  );
}
