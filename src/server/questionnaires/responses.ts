// Submitted answers with everything needed to read them: the version shown,
// the participant, the trial. A withdrawn participant's answers are left out.
import { and, asc, eq, ne } from "drizzle-orm";
import type { Database } from "@/store/client";
import {
  participants,
  questionnaireLinks,
  questionnaireResponses,
  questionnaireVersions,
  questionnaires,
} from "@/store/schema";

export async function submitted(db: Database, where: ReturnType<typeof eq>) {
  return db
    .select({
      questionnaire: questionnaires.name,
      version: questionnaireVersions.version,
      definition: questionnaireVersions.definition,
      participantCode: participants.code,
      trialId: questionnaireLinks.trialId,
      answers: questionnaireResponses.answers,
      score: questionnaireResponses.score,
      submittedAt: questionnaireResponses.submittedAt,
    })
    .from(questionnaireResponses)
    .innerJoin(questionnaireLinks, eq(questionnaireLinks.id, questionnaireResponses.linkId))
    .innerJoin(questionnaireVersions, eq(questionnaireVersions.id, questionnaireLinks.versionId))
    .innerJoin(questionnaires, eq(questionnaires.id, questionnaireVersions.questionnaireId))
    .innerJoin(participants, eq(participants.id, questionnaireLinks.participantId))
    .where(and(where, eq(questionnaireResponses.status, "submitted"), ne(participants.consentStatus, "withdrawn")))
    .orderBy(asc(participants.code), asc(questionnaires.name));
}
