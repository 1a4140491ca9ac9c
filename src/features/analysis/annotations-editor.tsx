"use client";
// Annotating afterwards, while watching the recording: at the playhead
// (or a typed time), and editing them later. The server decides who may edit.
import { useMutation, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Input } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

interface Annotation {
  id: string;
  relMs: number;
  label: string;
  note: string;
  authorName: string | null;
}

export function AnnotationsEditor({
  trialId,
  annotations,
  playheadMs,
}: {
  trialId: string;
  annotations: Annotation[];
  playheadMs: number | null;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.trials.annotations.queryKey({ trialId }) });
  const annotate = useMutation(trpc.trials.annotate.mutationOptions({ onSuccess: refresh }));
  const edit = useMutation(
    trpc.trials.editAnnotation.mutationOptions({ onSuccess: () => (setEditing(null), refresh()) }),
  );
  const [label, setLabel] = useState("");
  const [note, setNote] = useState("");
  const [seconds, setSeconds] = useState("");
  const [editing, setEditing] = useState<{ id: string; label: string; note: string } | null>(null);
  const at = seconds !== "" ? Number(seconds) * 1000 : (playheadMs ?? 0);
  const submit = (e: FormEvent) => {
    e.preventDefault();
    annotate.mutate(
      { trialId, relMs: Math.max(0, at), label, note },
      { onSuccess: () => (setLabel(""), setNote(""), setSeconds("")) },
    );
  };
  return (
    <section aria-label="Annotations" className="space-y-2">
      <h2 className="text-lg font-semibold">Annotations</h2>
      <Card className="space-y-3 p-4 text-sm">
        <form onSubmit={submit} className="flex flex-wrap items-end gap-2">
          <Input
            aria-label="What happened"
            placeholder="What happened"
            className="w-56"
            value={label}
            onChange={(e) => setLabel(e.target.value)}
          />
          <Input
            aria-label="Note (optional)"
            placeholder="Note (optional)"
            className="w-64"
            value={note}
            onChange={(e) => setNote(e.target.value)}
          />
          <Input
            aria-label="At (seconds)"
            placeholder={`${(at / 1000).toFixed(1)} s`}
            type="number"
            min={0}
            step="0.1"
            className="w-28"
            value={seconds}
            onChange={(e) => setSeconds(e.target.value)}
          />
          <Button type="submit" size="sm" disabled={!label.trim() || annotate.isPending}>
            Annotate at {(at / 1000).toFixed(1)} s
          </Button>
        </form>
        <Problem error={annotate.error ?? edit.error} />
        <ul className="divide-y divide-slate-100">
          {annotations.map((m) => (
            <li key={m.id} className="flex flex-wrap items-center gap-2 py-1.5">
              <span className="w-16 font-mono text-xs text-slate-500">{(m.relMs / 1000).toFixed(1)} s</span>
              {editing?.id === m.id ? (
                <>
                  <Input
                    aria-label="Edit what happened"
                    className="h-8 w-56"
                    value={editing.label}
                    onChange={(e) => setEditing({ ...editing, label: e.target.value })}
                  />
                  <Input
                    aria-label="Edit the note"
                    className="h-8 w-64"
                    value={editing.note}
                    onChange={(e) => setEditing({ ...editing, note: e.target.value })}
                  />
                  <Button
                    size="sm"
                    onClick={() => edit.mutate({ annotationId: m.id, label: editing.label, note: editing.note })}
                  >
                    Save
                  </Button>
                  <Button size="sm" variant="ghost" onClick={() => setEditing(null)}>
                    Cancel
                  </Button>
                </>
              ) : (
                <>
                  <strong>{m.label}</strong> <span className="text-slate-600">{m.note}</span>{" "}
                  <span className="text-xs text-slate-500">by {m.authorName ?? "someone"}</span>
                  <Button
                    size="sm"
                    variant="ghost"
                    className="ml-auto"
                    aria-label={`Edit “${m.label}”`}
                    onClick={() => setEditing({ id: m.id, label: m.label, note: m.note })}
                  >
                    Edit
                  </Button>
                </>
              )}
            </li>
          ))}
        </ul>
      </Card>
    </section>
  );
}
