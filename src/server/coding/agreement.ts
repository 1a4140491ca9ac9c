// Agreement between every two observers who coded the study's trials with
// one published scheme version: per trial, and pooled over all of them.
import { and, asc, eq, inArray, isNotNull } from "drizzle-orm";
import { agreement, type CodeMark, stepSpans } from "@/core/coding/agreement";
import type { Counted } from "@/core/coding/counted";
import type { Scheme } from "@/core/coding/scheme";
import type { Database } from "@/store/client";
import { codeEvents, participants, steps, trialEvents, trials, user } from "@/store/schema";

export async function studyAgreement(
  db: Database,
  studyId: string,
  versionId: string,
  scheme: Scheme,
  { sliceMs, window, stepIds }: Counted,
) {
  const rows = await db
    .select({
      code: codeEvents,
      observerName: user.name,
      t0: trials.t0,
      endedAt: trials.endedAt,
      participantCode: participants.code,
    })
    .from(codeEvents)
    .innerJoin(trials, eq(trials.id, codeEvents.trialId))
    .leftJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(user, eq(user.id, codeEvents.observerId))
    .where(and(eq(trials.studyId, studyId), eq(codeEvents.versionId, versionId)));
  const observers = new Map<string, string>();
  const byTrial = new Map<string, { label: string; durationMs: number; marks: Map<string, CodeMark[]> }>();
  for (const r of rows) {
    const observerId = r.code.observerId;
    if (!observerId) continue;
    observers.set(observerId, r.observerName ?? "(former member)");
    const trial = byTrial.get(r.code.trialId) ?? {
      label: r.participantCode ?? "rehearsal",
      // A finished trial lasts from t0 to its end; a running one as far as anyone has coded.
      durationMs: r.t0 && r.endedAt ? r.endedAt.getTime() - r.t0.getTime() : 0,
      marks: new Map(),
    };
    if (!(r.t0 && r.endedAt)) trial.durationMs = Math.max(trial.durationMs, r.code.endMs ?? r.code.startMs + 1);
    const marks = trial.marks.get(observerId) ?? [];
    marks.push(r.code);
    trial.marks.set(observerId, marks);
    byTrial.set(r.code.trialId, trial);
  }
  const entries = await stepEntries(db, [...byTrial.keys()]);
  const ids = [...observers.keys()].sort();
  const pairs = ids.flatMap((a, i) => ids.slice(i + 1).map((b) => [a, b] as const));
  return {
    // The sets' and codes' names, so the figures speak the scheme's words, not its ids.
    sets: scheme.sets.map((set) => ({
      id: set.id,
      name: set.name,
      codes: set.codes.map((code) => ({ id: code.id, name: code.name })),
    })),
    // The steps the coded trials went through, by name, for choosing the "steps" window.
    steps: await stepNames(db, [...new Set([...entries.values()].flat().map((e) => e.stepId))]),
    observers: ids.map((id) => ({ id, name: observers.get(id)! })),
    pairs: pairs.map(([a, b]) => {
      // Only the trials both coded: a trial one of them never watched says nothing about their agreement.
      const both = [...byTrial.entries()].filter(([, t]) => t.marks.has(a) && t.marks.has(b));
      const of = ([trialId, t]: (typeof both)[number]) => ({
        durationMs: t.durationMs,
        steps: stepSpans(entries.get(trialId) ?? [], t.durationMs),
        a: t.marks.get(a)!,
        b: t.marks.get(b)!,
      });
      return {
        a,
        b,
        pooled: agreement(scheme.sets, both.map(of), sliceMs, window, stepIds),
        trials: both.map(([trialId, t]) => ({
          trialId,
          label: t.label,
          sets: agreement(scheme.sets, [of([trialId, t])], sliceMs, window, stepIds),
        })),
      };
    }),
  };
}

/** Each trial's step entries in order, as relMs from its start. */
async function stepEntries(db: Database, trialIds: string[]) {
  const byTrial = new Map<string, Array<{ stepId: string; relMs: number }>>();
  if (trialIds.length === 0) return byTrial;
  const rows = await db
    .select({ trialId: trialEvents.trialId, stepId: trialEvents.stepId, relMs: trialEvents.relMs })
    .from(trialEvents)
    .where(
      and(
        inArray(trialEvents.trialId, trialIds),
        eq(trialEvents.type, "step.entered"),
        isNotNull(trialEvents.stepId),
        isNotNull(trialEvents.relMs),
      ),
    )
    .orderBy(asc(trialEvents.trialId), asc(trialEvents.seq));
  for (const r of rows)
    byTrial.set(r.trialId, [...(byTrial.get(r.trialId) ?? []), { stepId: r.stepId!, relMs: r.relMs! }]);
  return byTrial;
}

async function stepNames(db: Database, stepIds: string[]) {
  if (stepIds.length === 0) return [];
  const rows = await db
    .select({ id: steps.id, name: steps.name, position: steps.position })
    .from(steps)
    .where(inArray(steps.id, stepIds))
    .orderBy(asc(steps.position));
  return rows.map(({ id, name }) => ({ id, name }));
}
