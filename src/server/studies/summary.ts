// The study-level figures: every finished, non-rehearsal trial of a
// participant who has not withdrawn, folded into its fidelity report; and
// the same trials with the questionnaire scores, compared by condition.
//
// A trial's figures are folded from its log once, when first asked for after
// it ended, and kept (./fold-figures.ts); later reads take the kept
// copy while it is current, so the Results tab reads a row per trial rather
// than every trial's events. Who counts (withdrawn, rehearsal, condition) is
// decided here at each read, never kept.
import { and, asc, eq, inArray, ne, sql } from "drizzle-orm";
import { resultsByCondition } from "@/core/analysis/by-condition";
import { studySummary, type TrialFigures } from "@/core/analysis/study-summary";
import type { ReportFigures } from "@/core/analysis/trial-figures";
import type { Definition } from "@/core/questionnaires/definition";
import type { Database } from "@/store/client";
import { conditions, participants, questionnaireLinks, trialEvents, trialFigures, trials } from "@/store/schema";
import { isCurrent } from "@/store/trial-figures";
import { submitted } from "../questionnaires/responses";
import { foldFigures } from "./fold-figures";

export async function finishedTrials(db: Database, studyId: string): Promise<TrialFigures[]> {
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
  // A trial that is not a rehearsal always has a published version.
  const stale = rows.filter((r) => !isCurrent(r.kept, { versionId: r.versionId!, lastSeq: r.lastSeq }));
  const folded = await foldFigures(
    db,
    stale.map((r) => ({ id: r.id, versionId: r.versionId!, lastSeq: r.lastSeq })),
  );
  return rows.map((r) => ({
    trialId: r.id,
    participantCode: r.code,
    condition: r.condition,
    report: folded.get(r.id) ?? (r.kept!.figures as ReportFigures),
  }));
}

export async function studyFigures(db: Database, studyId: string) {
  return studySummary(await finishedTrials(db, studyId));
}

/** Each measure per condition; a questionnaire's score counts in its participant's condition. */
export async function studyResultsByCondition(db: Database, studyId: string) {
  const [figures, answers] = await Promise.all([
    finishedTrials(db, studyId),
    submitted(db, eq(questionnaireLinks.studyId, studyId)),
  ]);
  return resultsByCondition(
    figures,
    answers.map((a) => ({
      condition: a.condition,
      questionnaire: a.questionnaire,
      instrument: (a.definition as Definition).instrument ?? null,
      score: a.score,
    })),
  );
}
