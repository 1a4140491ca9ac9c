"use client";
// The form that makes a token, and the secret shown once after it.
import { useMutation, useQuery } from "@tanstack/react-query";
import { type FormEvent, useState } from "react";
import { EXPIRY_DAYS } from "@/core/access/access-token";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

export function NewToken({ onCreated }: { onCreated: () => void }) {
  const trpc = useTRPC();
  const studies = useQuery(trpc.tokens.studies.queryOptions());
  const [name, setName] = useState("");
  const [days, setDays] = useState("90");
  const [chosen, setChosen] = useState<string[]>([]);
  const [copied, setCopied] = useState(false);
  const create = useMutation(
    trpc.tokens.create.mutationOptions({
      onSuccess: () => {
        setName("");
        setChosen([]);
        setCopied(false);
        onCreated();
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate({ name, studyIds: chosen, expiresInDays: Number(days) });
  };
  const toggle = (id: string) => setChosen((c) => (c.includes(id) ? c.filter((s) => s !== id) : [...c, id]));
  const made = create.data;
  return (
    <Card className="space-y-4 p-5">
      <h2 className="font-semibold">Create a token</h2>
      {made && (
        <div className="space-y-2 rounded-md border border-green-300 bg-green-50 p-4" role="status">
          <p className="text-sm font-medium text-green-900">
            Your new token “{made.name}”. Copy it now: it will not be shown again.
          </p>
          <div className="flex flex-wrap items-center gap-2">
            <code data-testid="new-token" className="rounded bg-white px-2 py-1 font-mono text-sm break-all">
              {made.secret}
            </code>
            <Button
              variant="secondary"
              size="sm"
              onClick={async () => {
                await navigator.clipboard.writeText(made.secret);
                setCopied(true);
              }}
            >
              {copied ? "Copied" : "Copy token"}
            </Button>
          </div>
        </div>
      )}
      <form onSubmit={submit} className="space-y-4">
        <div className="grid gap-3 sm:grid-cols-2">
          <Field
            label="Name"
            required
            hint="What it is for, e.g. “Nightly analysis in R”."
            error={fieldError(create.error, "name")}
          >
            {(p) => <Input {...p} value={name} onChange={(e) => setName(e.target.value)} />}
          </Field>
          <Field
            label="Expires after (days)"
            required
            hint={`Between ${EXPIRY_DAYS.min} and ${EXPIRY_DAYS.max} days.`}
            error={fieldError(create.error, "expiresInDays")}
          >
            {(p) => (
              <Input
                {...p}
                type="number"
                min={EXPIRY_DAYS.min}
                max={EXPIRY_DAYS.max}
                value={days}
                onChange={(e) => setDays(e.target.value)}
              />
            )}
          </Field>
        </div>
        <fieldset>
          <legend className="text-sm font-medium text-slate-800">Studies it may read</legend>
          {studies.data?.length === 0 && (
            <p className="mt-1 text-sm text-slate-600">
              You are not the owner, a researcher or an observer of any study, so there is no data a token could read.
            </p>
          )}
          <div className="mt-2 grid gap-1 sm:grid-cols-2">
            {studies.data?.map((s) => (
              <label key={s.id} className="flex items-center gap-2 text-sm">
                <input type="checkbox" checked={chosen.includes(s.id)} onChange={() => toggle(s.id)} />
                {s.title} <span className="text-slate-500">({s.role})</span>
              </label>
            ))}
          </div>
          {fieldError(create.error, "studyIds") && (
            <p className="mt-1 text-sm text-red-700">{fieldError(create.error, "studyIds")}</p>
          )}
        </fieldset>
        <Button type="submit" disabled={create.isPending}>
          Create token
        </Button>
      </form>
      {create.error && !create.error.data?.issues && <Problem error={create.error} />}
    </Card>
  );
}
