"use client";
import { useMutation, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import type { StudyRole } from "@/core/access/policy";
import { studyRoleMay } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect, Textarea } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

type Study = { id: string; title: string; description: string; status: "draft" | "active" | "completed" | "archived"; settings: { requireConsent: boolean; assignment: unknown }; myRole: StudyRole };

export function OverviewTab({ study }: { study: Study }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const editable = studyRoleMay(study.myRole, "study.update");
  const [title, setTitle] = useState(study.title);
  const [description, setDescription] = useState(study.description);
  const [status, setStatus] = useState(study.status);
  const [requireConsent, setRequireConsent] = useState(study.settings.requireConsent);
  const update = useMutation(
    trpc.studies.update.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.studies.get.queryKey({ studyId: study.id }) }),
    }),
  );
  if (!editable) {
    return (
      <Card className="p-6">
        <h2 className="font-semibold">About this study</h2>
        <p className="mt-2 whitespace-pre-wrap text-slate-700">{study.description || "No description."}</p>
      </Card>
    );
  }
  const submit = (e: FormEvent) => {
    e.preventDefault();
    update.mutate({ studyId: study.id, title, description, status, settings: { requireConsent } });
  };
  return (
    <Card className="max-w-2xl p-6">
      <form onSubmit={submit} className="space-y-4">
        <Field label="Title" required error={fieldError(update.error, "title")}>
          {(p) => <Input {...p} value={title} onChange={(e) => setTitle(e.target.value)} />}
        </Field>
        <Field label="Description">{(p) => <Textarea {...p} value={description} onChange={(e) => setDescription(e.target.value)} />}</Field>
        <Field label="Status" hint="Active studies run trials; completed ones keep their data read-only.">
          {(p) => (
            <NativeSelect {...p} value={status} onChange={(e) => setStatus(e.target.value as Study["status"])}>
              {["draft", "active", "completed", "archived"].map((s) => (
                <option key={s} value={s}>
                  {s}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <label className="flex items-center gap-2 text-sm">
          <input type="checkbox" className="h-4 w-4" checked={requireConsent} onChange={(e) => setRequireConsent(e.target.checked)} />
          Trials need a participant whose consent is recorded
        </label>
        {update.error && !fieldError(update.error, "title") && <Problem error={update.error} />}
        <div className="flex items-center gap-3">
          <Button type="submit" disabled={update.isPending}>
            Save changes
          </Button>
          {update.isSuccess && <span className="text-sm text-emerald-700">Saved.</span>}
        </div>
      </form>
    </Card>
  );
}
