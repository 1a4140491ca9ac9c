"use client";
// Observers watch and annotate; every mark reaches everyone at once.
import { useState, type FormEvent } from "react";
import type { Viewer } from "@/core/socket/messages";
import { Button } from "@/ui/button";
import { Field, Input } from "@/ui/field";
import { Badge, Card, ROLE_TONE } from "@/ui/surface";
import type { Annotation } from "./use-trial-socket";

export function AnnotateForm({ annotate }: { annotate: (label: string, note: string) => Promise<{ ok: boolean }> }) {
  const [label, setLabel] = useState("");
  const [note, setNote] = useState("");
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    if (!label.trim()) return;
    if ((await annotate(label, note)).ok) {
      setLabel("");
      setNote("");
    }
  };
  return (
    <Card className="p-4">
      <h2 className="mb-2 font-semibold">Add an annotation</h2>
      <form onSubmit={submit} className="space-y-2">
        <Field label="Label" required>
          {(p) => (
            <Input
              {...p}
              value={label}
              onChange={(e) => setLabel(e.target.value)}
              placeholder="e.g. participant laughed"
            />
          )}
        </Field>
        <Field label="Note">{(p) => <Input {...p} value={note} onChange={(e) => setNote(e.target.value)} />}</Field>
        <Button type="submit">Annotate</Button>
      </form>
    </Card>
  );
}

export function AnnotationList({ annotations }: { annotations: Annotation[] }) {
  if (!annotations.length) return null;
  return (
    <Card className="p-4">
      <h2 className="mb-2 font-semibold">Annotations</h2>
      <ul className="space-y-1 text-sm" aria-label="Annotations">
        {annotations.map((a) => (
          <li key={a.id}>
            <span className="font-mono text-xs text-slate-500">{(a.relMs / 1000).toFixed(1)} s</span>{" "}
            <strong>{a.label}</strong>
            {a.note && <span className="text-slate-600"> — {a.note}</span>}{" "}
            <span className="text-xs text-slate-500">by {a.authorName}</span>
          </li>
        ))}
      </ul>
    </Card>
  );
}

export function Watching({ viewers }: { viewers: Viewer[] }) {
  return (
    <section className="flex flex-wrap items-center gap-2 text-sm" aria-label="Who is watching">
      <span className="text-slate-500">Connected:</span>
      {viewers.map((v) => (
        <Badge key={`${v.userId}-${v.role}`} tone={ROLE_TONE[v.role]}>
          {v.name} ({v.role})
        </Badge>
      ))}
    </section>
  );
}
