"use client";
// Coding a running trial: one key per code of the chosen published scheme,
// each code a button to tap on a tablet, the keys shown on screen, the states I hold lit, my last code said aloud
// for screen readers. Keys typed into a field (the annotation form) are text,
// not codes. What I code is mine alone: nobody else's codes are shown here.
import { useQuery } from "@tanstack/react-query";
import { useMemo, useState } from "react";
import { codeForKey, type Scheme } from "@/core/coding/scheme";
import { useTRPC } from "@/lib/trpc";
import { NativeSelect } from "@/ui/field";
import { Card } from "@/ui/surface";
import { isTyping, useKeys } from "@/ui/use-keys";
import type { LiveCode } from "../execution/use-trial-socket";

type Send = (mark: {
  schemeVersionId: string;
  setId: string;
  codeId: string;
}) => Promise<{ ok: true } | { ok: false; reason: string }>;

export function LiveCodingPanel({ trialId, codes, send }: { trialId: string; codes: LiveCode[]; send: Send }) {
  const trpc = useTRPC();
  const loaded = useQuery(trpc.coding.forTrial.queryOptions({ trialId }));
  const [chosen, setChosen] = useState<string | null>(null);
  const [last, setLast] = useState<string>("");
  /** A code the runtime did not mark, and why: said, so a press is never lost without a word. */
  const [notMarked, setNotMarked] = useState<string | null>(null);
  const schemes = loaded.data?.schemes ?? [];
  const current = schemes.find((s) => s.versionId === chosen) ?? schemes[0];
  // Mine: those loaded with the page, updated by what the runtime confirmed since.
  const mine = useMemo(() => {
    const byId = new Map((loaded.data?.mine ?? []).map((c) => [c.id, c as LiveCode]));
    for (const c of codes) byId.set(c.id, c);
    return [...byId.values()].filter((c) => c.versionId === current?.versionId);
  }, [loaded.data, codes, current]);

  // A key and a tap mark the same way: on a tablet there is no keyboard.
  const mark = (setId: string, code: { id: string; name: string }) => {
    if (!current) return;
    void send({ schemeVersionId: current.versionId, setId, codeId: code.id }).then((r) => {
      if (r.ok) {
        setLast(code.name);
        setNotMarked(null);
      } else setNotMarked(`“${code.name}” was not marked: ${r.reason}`);
    });
  };
  useKeys((e) => {
    if (!current || e.repeat || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
    const found = codeForKey(current.definition as Scheme, e.key);
    if (!found) return;
    e.preventDefault();
    mark(found.set.id, found.code);
  });

  if (!current) return null;
  const scheme = current.definition as Scheme;
  const holding = new Set(
    mine.filter((c) => c.kind === "state" && c.endMs === null).map((c) => `${c.setId}/${c.codeId}`),
  );
  return (
    <Card className="space-y-3 p-4" aria-label="Coding">
      <h2 className="font-semibold">Coding</h2>
      {schemes.length > 1 && (
        <NativeSelect aria-label="Coding scheme" value={current.versionId} onChange={(e) => setChosen(e.target.value)}>
          {schemes.map((s) => (
            <option key={s.versionId} value={s.versionId}>
              {(s.definition as Scheme).name} (version {s.version})
            </option>
          ))}
        </NativeSelect>
      )}
      <p className="text-xs text-slate-600">
        Press or tap a code while you watch. A state holds until you press or tap it again, or another of its set.
      </p>
      {scheme.sets.map((set) => (
        <section key={set.id} aria-label={set.name}>
          <h3 className="text-sm font-medium">{set.name}</h3>
          <ul className="mt-1 grid grid-cols-2 gap-1 text-sm">
            {set.codes.map((code) => {
              const held = holding.has(`${set.id}/${code.id}`);
              return (
                <li key={code.id} data-held={held || undefined}>
                  <button
                    type="button"
                    aria-pressed={code.kind === "state" ? held : undefined}
                    onClick={() => mark(set.id, code)}
                    className={`flex w-full items-center gap-2 rounded border px-2 py-1 text-left hover:bg-slate-50 pointer-coarse:min-h-11 ${held ? "border-slate-900 bg-slate-100 font-semibold" : "border-slate-200"}`}
                  >
                    <kbd className="rounded border border-slate-300 bg-white px-1.5 font-mono text-xs">{code.key}</kbd>
                    <span className="inline-block h-2.5 w-2.5 rounded-full" style={{ background: code.colour }} />
                    {code.name}
                    {code.kind === "state" && <span className="sr-only">{held ? "(holding)" : "(state)"}</span>}
                  </button>
                </li>
              );
            })}
          </ul>
        </section>
      ))}
      <p className="text-sm text-slate-700" aria-live="polite">
        {mine.length} code{mine.length === 1 ? "" : "s"} marked
        {last && <span>; last: {last}</span>}
      </p>
      {notMarked && (
        <p role="alert" className="text-sm text-red-700">
          {notMarked}
        </p>
      )}
    </Card>
  );
}
