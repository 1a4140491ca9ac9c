"use client";
// Inter-rater agreement as a paper reports it: Cohen's kappa per set of codes
// between two chosen observers, over time slices, with the confusion table it
// comes from; pooled over the study's trials, or for one trial.
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState } from "react";
import { type SetAgreement, strength } from "@/core/coding/agreement";
import {
  AGREEMENT_WINDOWS,
  type AgreementWindow,
  type Counted,
  countedWords,
  sameCount,
  WINDOW_WORDS,
} from "@/core/coding/counted";
import { Button } from "@/ui/button";
import { useTRPC } from "@/lib/trpc";
import { Field, NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Card, Spinner } from "@/ui/surface";
import { Table, Td, Th } from "@/ui/table";

const SLICES = [500, 1000, 2000, 5000];

export function AgreementPanel({
  studyId,
  trialId,
  canKeep = false,
}: {
  studyId: string;
  trialId?: string;
  /** May keep what is counted with the scheme (an editor, on the study's Results tab). */
  canKeep?: boolean;
}) {
  const trpc = useTRPC();
  const schemes = useQuery(trpc.coding.schemes.queryOptions({ studyId }));
  const published = (schemes.data ?? []).filter((s) => s.latestVersionId);
  const [schemeId, setSchemeId] = useState<string | null>(null);
  const scheme = published.find((s) => s.id === schemeId) ?? published[0];
  if (schemes.error) return <Problem error={schemes.error} />;
  if (!scheme) return null;
  return (
    <section aria-label="Agreement between observers" className="space-y-3">
      <h2 className="text-lg font-semibold">Agreement between observers</h2>
      {published.length > 1 && (
        <NativeSelect
          aria-label="Coding scheme"
          className="w-72"
          value={scheme.id}
          onChange={(e) => setSchemeId(e.target.value)}
        >
          {published.map((s) => (
            <option key={s.id} value={s.id}>
              {s.name} (version {s.latestVersion})
            </option>
          ))}
        </NativeSelect>
      )}
      <Pair schemeId={scheme.id} versionId={scheme.latestVersionId!} trialId={trialId} canKeep={canKeep} />
    </section>
  );
}

function Pair({
  schemeId,
  versionId,
  trialId,
  canKeep,
}: {
  schemeId: string;
  versionId: string;
  trialId?: string;
  canKeep: boolean;
}) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  // Null: as the scheme keeps it (the server says what that is).
  const [asked, setAsked] = useState<Counted | null>(null);
  const [chosen, setChosen] = useState<[string, string] | null>(null);
  const result = useQuery(trpc.coding.agreement.queryOptions({ schemeVersionId: versionId, ...asked }));
  const keep = useMutation(
    trpc.coding.keepCounted.mutationOptions({
      onSuccess: () => queryClient.invalidateQueries({ queryKey: trpc.coding.agreement.queryKey() }),
    }),
  );
  if (result.isPending) return <Spinner label="Comparing the observers…" />;
  if (result.error) return <Problem error={result.error} />;
  const { sets: named, observers, pairs, steps, counted, kept } = result.data;
  const { sliceMs, window, stepIds } = counted;
  const choose = (change: Partial<Counted>) => setAsked({ ...counted, ...change });
  const unkept = !sameCount(counted, kept);
  if (observers.length < 2)
    return (
      <p className="text-sm text-slate-600">
        Agreement needs two observers who coded the same trial with this scheme; {observers.length || "none"} coded so
        far.
      </p>
    );
  const [a, b] = chosen ?? [pairs[0]!.a, pairs[0]!.b];
  const pair = pairs.find((p) => (p.a === a && p.b === b) || (p.a === b && p.b === a));
  const sets = trialId ? pair?.trials.find((t) => t.trialId === trialId)?.sets : pair?.pooled;
  const nameOf = (id: string) => observers.find((o) => o.id === id)?.name ?? id;
  const pick = (which: 0 | 1, id: string) => setChosen(which === 0 ? [id, b] : [a, id]);
  return (
    <div className="space-y-3">
      <div className="flex flex-wrap items-end gap-3 text-sm">
        {([0, 1] as const).map((which) => (
          <Field key={which} label={which === 0 ? "First observer" : "Second observer"}>
            {(p) => (
              <NativeSelect {...p} value={which === 0 ? a : b} onChange={(e) => pick(which, e.target.value)}>
                {observers.map((o) => (
                  <option key={o.id} value={o.id}>
                    {o.name}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        ))}
        <Field label="Time slice">
          {(p) => (
            <NativeSelect {...p} value={sliceMs} onChange={(e) => choose({ sliceMs: Number(e.target.value) })}>
              {SLICES.map((ms) => (
                <option key={ms} value={ms}>
                  {ms / 1000} s
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <Field label="Counted">
          {(p) => (
            <NativeSelect {...p} value={window} onChange={(e) => choose({ window: e.target.value as AgreementWindow })}>
              {AGREEMENT_WINDOWS.map((w) => (
                <option key={w} value={w}>
                  {WINDOW_WORDS[w]}
                </option>
              ))}
            </NativeSelect>
          )}
        </Field>
      </div>
      {window === "steps" && (
        <fieldset className="flex flex-wrap gap-3 text-sm">
          <legend className="sr-only">Steps counted</legend>
          {steps.map((step) => (
            <label key={step.id} className="flex items-center gap-1">
              <input
                type="checkbox"
                checked={stepIds.includes(step.id)}
                onChange={(e) =>
                  choose({
                    stepIds: e.target.checked ? [...stepIds, step.id] : stepIds.filter((id) => id !== step.id),
                  })
                }
              />
              {step.name}
            </label>
          ))}
        </fieldset>
      )}
      {canKeep && (
        <p className="flex flex-wrap items-center gap-2 text-sm text-slate-600">
          {unkept
            ? `The methods text counts ${countedWords(kept, steps)}.`
            : "The methods text counts agreement as shown here."}
          {unkept && (
            <Button
              variant="secondary"
              size="sm"
              disabled={keep.isPending}
              onClick={() => keep.mutate({ codingSchemeId: schemeId, counted })}
            >
              Keep this count for the methods text
            </Button>
          )}
        </p>
      )}
      <Problem error={keep.error} />
      {a === b || !pair || !sets ? (
        <p className="text-sm text-slate-600">
          {a === b ? "Choose two different observers." : "These two observers have not coded the same trial."}
        </p>
      ) : (
        <>
          <p className="text-sm text-slate-600">
            {nameOf(pair.a)} (rows) and {nameOf(pair.b)} (columns),{" "}
            {trialId
              ? "in this trial"
              : `pooled over ${pair.trials.length} trial${pair.trials.length === 1 ? "" : "s"} both coded`}
            .
          </p>
          {sets.map((s) => (
            <SetFigure
              key={s.setId}
              set={s}
              names={named.find((n) => n.id === s.setId)}
              counted={countedWords(counted, steps)}
            />
          ))}
        </>
      )}
    </div>
  );
}

type SetNames = { name: string; codes: Array<{ id: string; name: string }> };

function SetFigure({ set, names, counted }: { set: SetAgreement; names?: SetNames; counted: string }) {
  const kappa = set.kappa === null ? "undefined" : set.kappa.toFixed(2);
  const setName = names?.name ?? set.setId;
  // "(none)" is no code's id (ids are slugs): it stays as it is.
  const codeName = (id: string) => names?.codes.find((c) => c.id === id)?.name ?? id;
  return (
    <Card className="space-y-2 p-3">
      <h3 className="font-medium">
        {setName}: Cohen&apos;s κ = <span data-kappa={set.setId}>{kappa}</span>
        {set.kappa !== null && <span className="text-slate-600"> ({strength(set.kappa)})</span>}
        <span className="text-sm font-normal text-slate-600" data-window>
          {" "}
          · {counted}
        </span>
      </h3>
      <p className="text-xs text-slate-600">
        {set.n} slices, observed agreement {(set.observed * 100).toFixed(1)} %, expected by chance{" "}
        {(set.expected * 100).toFixed(1)} %.
        {set.kappa === null && " Kappa is undefined where chance agreement is certain (both always coded the same)."}
      </p>
      <Table aria-label={`Confusion table of ${setName}`}>
        <thead>
          <tr>
            <Th />
            {set.table.categories.map((c) => (
              <Th key={c}>{codeName(c)}</Th>
            ))}
          </tr>
        </thead>
        <tbody>
          {set.table.counts.map((row, i) => (
            <tr key={i}>
              <Th scope="row">{codeName(set.table.categories[i]!)}</Th>
              {row.map((n, j) => (
                <Td key={j} className={i === j ? "font-semibold" : undefined}>
                  {n}
                </Td>
              ))}
            </tr>
          ))}
        </tbody>
      </Table>
    </Card>
  );
}
