// The study-level figures: every finished, non-rehearsal trial of a
// participant who has not withdrawn, folded into its fidelity report; and
// the same trials with the questionnaire scores, compared by condition.
import { and, asc, eq, inArray, ne } from "drizzle-orm";
import { resultsByCondition } from "@/core/analysis/by-condition";
import { fidelityReport } from "@/core/analysis/fidelity";
import { studySummary, type TrialFigures } from "@/core/analysis/study-summary";
import type { TrialEvent } from "@/core/trial";
import type { Database } from "@/store/client";
import { conditions, experimentVersions, participants, questionnaireLinks, trials } from "@/store/schema";
import { eventsOfTrials } from "@/store/event-store";
import { submitted } from "../questionnaires/responses";

async function finishedTrials(db: Database, studyId: string): Promise<TrialFigures[]> {
  const rows = await db
    .select({
      id: trials.id,
      code: participants.code,
      condition: conditions.name,
      protocol: experimentVersions.snapshot,
    })
    .from(trials)
    .innerJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(conditions, eq(conditions.id, participants.conditionId))
    .where(
      and(
        eq(trials.studyId, studyId),
        eq(trials.isRehearsal, false),
        ne(participants.consentStatus, "withdrawn"),
        inArray(trials.status, ["completed", "aborted"]),
      ),
    )
    .orderBy(asc(trials.createdAt));
  // A hundred trials' events in one query at a time (not a query per trial), each batch
  // folded into reports and let go before the next is read.
  const figures: TrialFigures[] = [];
  for (let start = 0; start < rows.length; start += 100) {
    const batch = rows.slice(start, start + 100);
    const events = await eventsOfTrials(
      db,
      batch.map((r) => r.id),
    );
    for (const r of batch)
      figures.push({
        trialId: r.id,
        participantCode: r.code,
        condition: r.condition,
        report: fidelityReport(r.protocol, events.get(r.id) as unknown as TrialEvent[]),
      });
  }
  return figures;
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
