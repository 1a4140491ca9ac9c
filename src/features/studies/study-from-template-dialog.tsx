"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useRouter } from "next/navigation";
import { useState, type FormEvent } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";

/** A new study from one of mine as a template: its design, never its participants or data. */
export function StudyFromTemplateDialog() {
  const trpc = useTRPC();
  const router = useRouter();
  const queryClient = useQueryClient();
  const [open, setOpen] = useState(false);
  const [sourceId, setSourceId] = useState("");
  const [title, setTitle] = useState("");
  const studies = useQuery(trpc.studies.mine.queryOptions());
  const create = useMutation(
    trpc.studies.createFromTemplate.mutationOptions({
      onSuccess: async (study) => {
        await queryClient.invalidateQueries({ queryKey: trpc.studies.mine.queryKey() });
        setOpen(false);
        router.push(`/studies/${study.id}`);
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate({ studyId: sourceId, title });
  };
  return (
    <Dialog
      title="New study from another"
      description="Copies the study's settings, experiments, conditions and questionnaires as drafts. Never its participants, sessions, trials, recordings or answers; you become the new study's owner and only member."
      open={open}
      onOpenChange={setOpen}
      trigger={<Button variant="secondary">New study from…</Button>}
    >
      <form onSubmit={submit} className="space-y-4">
        <Field label="Start from" required error={fieldError(create.error, "studyId")}>
          {(p) => (
            <NativeSelect
              {...p}
              required
              value={sourceId}
              onChange={(e) => {
                setSourceId(e.target.value);
                const source = studies.data?.find((s) => s.id === e.target.value);
                if (source && !title) setTitle(`${source.title} (new)`.slice(0, 200));
              }}
            >
              <option value="" disabled>
                Choose a study…
              </option>
              {studies.data?.map((s) => (
                <option key={s.id} value={s.id}>
                  {s.title}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <Field label="Title" required error={fieldError(create.error, "title")}>
          {(p) => <Input {...p} value={title} onChange={(e) => setTitle(e.target.value)} />}
        </Field>
        {create.error && !fieldError(create.error, "title") && !fieldError(create.error, "studyId") && (
          <Problem error={create.error} />
        )}
        <Problem error={studies.error} />
        <div className="flex justify-end gap-2">
          <Button variant="secondary" onClick={() => setOpen(false)}>
            Cancel
          </Button>
          <Button type="submit" disabled={create.isPending || !sourceId}>
            Create study
          </Button>
        </div>
      </form>
    </Dialog>
  );
}
