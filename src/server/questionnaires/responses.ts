// Submitted answers with everything needed to read them: the version shown,
// the participant and their condition, the trial. A withdrawn participant's answers are left out.
// In participant code and questionnaire name order (ties in response order).
import { and, asc, eq, ne, type SQL } from "drizzle-orm";
import type { Database } from "@/store/client";
import { after, keyedPages } from "@/store/pages";
import {
  conditions,
  participants,
  questionnaireLinks,
  questionnaireResponses,
  questionnaireVersions,
  questionnaires,
} from "@/store/schema";

/** The submitted answers `where` picks, at most `limit` if given; each with its response's id, the key a page ends at. */
function submittedRows(db: Database, where: SQL | undefined, limit?: number) {
  const query = db
    .select({
      questionnaire: questionnaires.name,
      version: questionnaireVersions.version,
      definition: questionnaireVersions.definition,
      participantCode: participants.code,
      condition: conditions.name,
      trialId: questionnaireLinks.trialId,
      answers: questionnaireResponses.answers,
      score: questionnaireResponses.score,
      submittedAt: questionnaireResponses.submittedAt,
      responseId: questionnaireResponses.id,
    })
    .from(questionnaireResponses)
    .innerJoin(questionnaireLinks, eq(questionnaireLinks.id, questionnaireResponses.linkId))
    .innerJoin(questionnaireVersions, eq(questionnaireVersions.id, questionnaireLinks.versionId))
    .innerJoin(questionnaires, eq(questionnaires.id, questionnaireVersions.questionnaireId))
    .innerJoin(participants, eq(participants.id, questionnaireLinks.participantId))
    .leftJoin(conditions, eq(conditions.id, participants.conditionId))
    .where(and(where, eq(questionnaireResponses.status, "submitted"), ne(participants.consentStatus, "withdrawn")))
    .orderBy(asc(participants.code), asc(questionnaires.name), asc(questionnaireResponses.id))
    .$dynamic();
  return limit ? query.limit(limit) : query;
}

export async function submitted(db: Database, where: SQL) {
  return (await submittedRows(db, where)).map(({ responseId: _, ...row }) => row);
}

/** One trial's submitted answers a page at a time (see keyedPages), in submitted's order. */
export function submittedPages(db: Database, trialId: string, limit: number) {
  const key = [participants.code, questionnaires.name, questionnaireResponses.id];
  return keyedPages(
    async (from) => submittedRows(db, and(eq(questionnaireLinks.trialId, trialId), after(key, from)), limit),
    (q) => [q.participantCode, q.questionnaire, q.responseId],
    limit,
  );
}
