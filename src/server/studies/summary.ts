// The study-level figures: every finished, non-rehearsal trial of a
// participant who has not withdrawn, folded into its fidelity report; and
// the same trials with the questionnaire scores, compared by condition.
//
// A trial's figures are folded from its log once, when first asked for after
// it ended, and kept (src/store/trial-figures.ts); later reads take the kept
// copy while it is current, so the Results tab reads a row per trial rather
// than every trial's events. Who counts (withdrawn, rehearsal, condition) is
// decided here at each read, never kept.
import { and, asc, eq, inArray, ne, sql } from "drizzle-orm";
import { resultsByCondition } from "@/core/analysis/by-condition";
import { fidelityReport } from "@/core/analysis/fidelity";
import { studySummary, type TrialFigures } from "@/core/analysis/study-summary";
import { type ReportFigures, reportFigures } from "@/core/analysis/trial-figures";
import type { TrialEvent } from "@/core/trial";
import type { Database } from "@/store/client";
import {
  conditions,
  experimentVersions,
  participants,
  questionnaireLinks,
  trialEvents,
  trialFigures,
  trials,
} from "@/store/schema";
import { eventsOfTrials } from "@/store/event-store";
import { isCurrent, type KeptFigures, keepFigures } from "@/store/trial-figures";
import { submitted } from "../questionnaires/responses";

/** A hundred trials' events are read in one query, folded, and let go before the next hundred. */
const FOLD_BATCH = 100;

async function finishedTrials(db: Database, studyId: string): Promise<TrialFigures[]> {
  const rows = await db
    .select({
      id: trials.id,
      code: participants.code,
      condition: conditions.name,
      versionId: trials.versionId,
      // The primary key's index answers this with one probe per trial.
      lastSeq:
        sql<number>`coalesce((select max(${trialEvents.seq}) from ${trialEvents} where ${trialEvents.trialId} = ${trials.id}), 0)`.mapWith(
          Number,
        ),
      kept: {
        figuresVersion: trialFigures.figuresVersion,
        versionId: trialFigures.versionId,
        lastSeq: trialFigures.lastSeq,
        figures: trialFigures.figures,
      },
    })
    .from(trials)
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(conditions, eq(conditions.id, participants.conditionId))
    .leftJoin(trialFigures, eq(trialFigures.trialId, trials.id))
    .where(
      and(
        eq(trials.studyId, studyId),
        eq(trials.isRehearsal, false),
        ne(participants.consentStatus, "withdrawn"),
        inArray(trials.status, ["completed", "aborted"]),
      ),
    )
    .orderBy(asc(trials.createdAt));
  const figures = new Map<string, ReportFigures>();
  const stale: typeof rows = [];
  for (const r of rows) {
    // A trial that is not a rehearsal always has a published version.
    if (isCurrent(r.kept, { versionId: r.versionId!, lastSeq: r.lastSeq }))
      figures.set(r.id, r.kept!.figures as ReportFigures);
    else stale.push(r);
  }
  for (const kept of await foldAndKeep(
    db,
    stale.map((r) => ({ id: r.id, versionId: r.versionId! })),
  ))
    figures.set(kept.trialId, kept.figures);
  return rows.map((r) => ({
    trialId: r.id,
    participantCode: r.code,
    condition: r.condition,
    report: figures.get(r.id)!,
  }));
}

/** Folds these trials' logs into their figures, a batch at a time, and keeps them. */
async function foldAndKeep(db: Database, stale: Array<{ id: string; versionId: string }>): Promise<KeptFigures[]> {
  if (!stale.length) return [];
  const versionIds = [...new Set(stale.map((t) => t.versionId))];
  const protocols = new Map(
    (
      await db
        .select({ id: experimentVersions.id, snapshot: experimentVersions.snapshot })
        .from(experimentVersions)
        .where(inArray(experimentVersions.id, versionIds))
    ).map((v) => [v.id, v.snapshot]),
  );
  const kept: KeptFigures[] = [];
  for (let start = 0; start < stale.length; start += FOLD_BATCH) {
    const batch = stale.slice(start, start + FOLD_BATCH);
    const events = await eventsOfTrials(
      db,
      batch.map((t) => t.id),
    );
    const folded = batch.map(({ id, versionId }) => {
      const log = events.get(id)!;
      return {
        trialId: id,
        versionId,
        // The last event folded, not the one seen before reading: an event appended meanwhile makes it stale.
        lastSeq: log.at(-1)?.seq ?? 0,
        figures: reportFigures(fidelityReport(protocols.get(versionId)!, log as unknown as TrialEvent[])),
      };
    });
    await keepFigures(db, folded);
    kept.push(...folded);
  }
  return kept;
}

export async function studyFigures(db: Database, studyId: string) {
  return studySummary(await finishedTrials(db, studyId));
}

/** Each measure per condition; a questionnaire's score counts in its participant's condition. */
export async function studyResultsByCondition(db: Database, studyId: string) {
  const [figures, answers, assigned] = await Promise.all([
    finishedTrials(db, studyId),
    submitted(db, eq(questionnaireLinks.studyId, studyId)),
    db
      .select({ code: participants.code, condition: conditions.name })
      .from(participants)
      .leftJoin(conditions, eq(conditions.id, participants.conditionId))
      .where(eq(participants.studyId, studyId)),
  ]);
  const conditionOf = new Map(assigned.map((p) => [p.code, p.condition]));
  return resultsByCondition(
    figures,
    answers.map((a) => ({
      condition: conditionOf.get(a.participantCode) ?? null,
      questionnaire: a.questionnaire,
      score: a.score,
    })),
  );
}
