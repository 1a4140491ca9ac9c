"use client";
// Each observer's codes of a trial as their own tier, beside the recording:
// I add codes of mine at the playhead (or a typed time), move and delete
// mine; everyone else's tiers are read only (the server refuses otherwise).
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState } from "react";
import type { Scheme } from "@/core/coding/scheme";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

const sec = (ms: number | null) => (ms === null ? "" : (ms / 1000).toFixed(1));
const ms = (text: string) => (text.trim() === "" ? null : Math.max(0, Math.round(Number(text) * 1000)));

export function CodeTiers({
  trialId,
  playheadMs,
  mineOnly = false,
}: {
  trialId: string;
  playheadMs: number | null;
  /** My tier alone: for a coder who may not read the results (everyone's codes are results), e.g. blind to condition. */
  mineOnly?: boolean;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const everyone = useQuery({ ...trpc.coding.codes.queryOptions({ trialId }), enabled: !mineOnly });
  // Read afresh: codes marked live came over the trial's socket, past this query's last answer.
  const mine = useQuery({ ...trpc.coding.forTrial.queryOptions({ trialId }), refetchOnMount: "always" });
  const codes = mineOnly
    ? { data: mine.data?.mine.map((c) => ({ ...c, observerName: "My codes" })), error: mine.error }
    : everyone;
  const refresh = () => queryClient.invalidateQueries();
  const add = useMutation(trpc.coding.addCode.mutationOptions({ onSuccess: refresh }));
  const move = useMutation(trpc.coding.moveCode.mutationOptions({ onSuccess: refresh }));
  const remove = useMutation(trpc.coding.deleteCode.mutationOptions({ onSuccess: refresh }));
  const [choice, setChoice] = useState("");
  const [start, setStart] = useState("");
  const [end, setEnd] = useState("");
  const schemes = mine.data?.schemes ?? [];
  if (!schemes.length && !codes.data?.length) return null;
  const myIds = new Set((mine.data?.mine ?? []).map((c) => c.id));
  const nameOf = new Map(
    schemes.flatMap((s) =>
      (s.definition as Scheme).sets.flatMap((set) =>
        set.codes.map((c) => [`${s.versionId}/${set.id}/${c.id}`, { set: set.name, code: c.name, colour: c.colour }]),
      ),
    ),
  );
  const tiers = new Map<string, NonNullable<typeof codes.data>>();
  for (const c of codes.data ?? []) {
    const key = `${c.observerName} - ${nameOf.get(`${c.versionId}/${c.setId}/${c.codeId}`)?.set ?? c.setId}`;
    tiers.set(key, [...(tiers.get(key) ?? []), c]);
  }
  const options = schemes.flatMap((s) =>
    (s.definition as Scheme).sets.flatMap((set) =>
      set.codes.map((c) => ({
        value: `${s.versionId}/${set.id}/${c.id}`,
        label: `${set.name}: ${c.name}`,
        kind: c.kind,
      })),
    ),
  );
  const chosen = options.find((o) => o.value === choice) ?? options[0];
  const at = ms(start) ?? playheadMs ?? 0;
  return (
    <Card className="space-y-3 p-4">
      <h2 className="font-semibold">Codes</h2>
      {[...tiers.entries()].map(([tier, list]) => (
        <section key={tier} aria-label={`Tier ${tier}`}>
          <h3 className="text-sm font-medium">{tier}</h3>
          <ul className="mt-1 space-y-1 text-sm">
            {list.map((c) => {
              const names = nameOf.get(`${c.versionId}/${c.setId}/${c.codeId}`);
              return (
                <li key={c.id} className="flex items-center gap-2">
                  <span className="inline-block h-2.5 w-2.5 rounded-full" style={{ background: names?.colour }} />
                  <span className="font-mono text-xs text-slate-600">
                    {sec(c.startMs)} s
                    {/* A state never ended holds to the trial's end (so agreement counts it): not a moment. */}
                    {c.endMs !== null ? ` – ${sec(c.endMs)} s` : c.kind === "state" && " – held to the end"}
                  </span>
                  {names?.code ?? c.codeId}
                  {c.modifiers.length > 0 && <span className="text-slate-600">({c.modifiers.join(", ")})</span>}
                  {myIds.has(c.id) && (
                    <span className="ml-auto flex gap-1">
                      <Button
                        variant="ghost"
                        size="sm"
                        // The visible words first: a name must hold what the button shows (WCAG 2.5.3).
                        aria-label={`Move to playhead: ${names?.code ?? c.codeId} at ${sec(c.startMs)} s`}
                        disabled={playheadMs === null}
                        onClick={() =>
                          move.mutate({
                            codeEventId: c.id,
                            startMs: playheadMs ?? c.startMs,
                            endMs: c.endMs === null ? null : (playheadMs ?? c.startMs) + (c.endMs - c.startMs),
                          })
                        }
                      >
                        Move to playhead
                      </Button>
                      <Button
                        variant="ghost"
                        size="sm"
                        aria-label={`Delete ${names?.code ?? c.codeId} at ${sec(c.startMs)} s`}
                        onClick={() => remove.mutate({ codeEventId: c.id })}
                      >
                        Delete
                      </Button>
                    </span>
                  )}
                </li>
              );
            })}
          </ul>
        </section>
      ))}
      {chosen && (
        <form
          className="flex flex-wrap items-end gap-2"
          onSubmit={(e) => {
            e.preventDefault();
            const [schemeVersionId, setId, codeId] = chosen.value.split("/") as [string, string, string];
            add.mutate({
              trialId,
              schemeVersionId,
              setId,
              codeId,
              startMs: at,
              endMs: chosen.kind === "state" ? ms(end) : null,
            });
          }}
        >
          <Field label="Code">
            {(p) => (
              <NativeSelect {...p} value={chosen.value} onChange={(e) => setChoice(e.target.value)}>
                {options.map((o) => (
                  <option key={o.value} value={o.value}>
                    {o.label}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
          <Field label="Start (s)" hint="empty: the playhead">
            {(p) => (
              <Input
                {...p}
                className="w-24"
                inputMode="decimal"
                value={start}
                onChange={(e) => setStart(e.target.value)}
              />
            )}
          </Field>
          {chosen.kind === "state" && (
            <Field label="End (s)">
              {(p) => (
                <Input
                  {...p}
                  className="w-24"
                  inputMode="decimal"
                  value={end}
                  onChange={(e) => setEnd(e.target.value)}
                />
              )}
            </Field>
          )}
          <Button type="submit" disabled={add.isPending}>
            Add a code
          </Button>
        </form>
      )}
      <Problem error={codes.error ?? add.error ?? move.error ?? remove.error} />
    </Card>
  );
}
