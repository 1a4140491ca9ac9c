"use client";
import { useMutation, useQueryClient } from "@tanstack/react-query";
import { useRouter } from "next/navigation";
import { useState, type FormEvent } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Dialog } from "@/ui/dialog";
import { Field, Input, Textarea } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";

export function NewStudyDialog() {
  const trpc = useTRPC();
  const router = useRouter();
  const queryClient = useQueryClient();
  const [open, setOpen] = useState(false);
  const [title, setTitle] = useState("");
  const [description, setDescription] = useState("");
  const create = useMutation(
    trpc.studies.create.mutationOptions({
      onSuccess: async (study) => {
        await queryClient.invalidateQueries({ queryKey: trpc.studies.mine.queryKey() });
        setOpen(false);
        router.push(`/studies/${study.id}`);
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate({ title, description });
  };
  return (
    <Dialog
      title="New study"
      description="A study holds its experiments, participants and trials."
      open={open}
      onOpenChange={setOpen}
      trigger={<Button>New study</Button>}
    >
      <form onSubmit={submit} className="space-y-4">
        <Field label="Title" required error={fieldError(create.error, "title")}>
          {(p) => <Input {...p} value={title} onChange={(e) => setTitle(e.target.value)} autoFocus />}
        </Field>
        <Field label="Description" hint="What question does this study answer?">
          {(p) => <Textarea {...p} value={description} onChange={(e) => setDescription(e.target.value)} />}
        </Field>
        {create.error && !fieldError(create.error, "title") && <Problem error={create.error} />}
        <div className="flex justify-end gap-2">
          <Button variant="secondary" onClick={() => setOpen(false)}>
            Cancel
          </Button>
          <Button type="submit" disabled={create.isPending}>
            Create study
          </Button>
        </div>
      </form>
    </Dialog>
  );
}
