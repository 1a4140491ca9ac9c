// One-time links: the participant's way in, with no account. The token is a
// random secret shown once; only its hash is stored. A link is bound to one
// participant (and trial), expires, and closes when its answers are submitted.
import { createHash, randomBytes } from "node:crypto";
import { TRPCError } from "@trpc/server";
import { and, eq } from "drizzle-orm";
import { presentedOrder, type Answers } from "@/core/questionnaires/answers";
import type { Definition } from "@/core/questionnaires/definition";
import { readSettings, shownTitle } from "@/core/studies/settings";
import type { Database } from "@/store/client";
import {
  participants,
  questionnaireLinks,
  questionnaireResponses,
  questionnaireVersions,
  questionnaires,
  studies,
} from "@/store/schema";

export const hashToken = (token: string) => createHash("sha256").update(token).digest("hex");

export function newToken(): string {
  return randomBytes(24).toString("base64url");
}

/** The link behind a token, or a refusal that tells the participant what to do. */
export async function openLink(db: Database, token: string) {
  const [row] = await db
    .select({
      link: questionnaireLinks,
      definition: questionnaireVersions.definition,
      version: questionnaireVersions.version,
      name: questionnaires.name,
      studyTitle: studies.title,
      settings: studies.settings,
      participantCode: participants.code,
      consentStatus: participants.consentStatus,
      response: questionnaireResponses,
    })
    .from(questionnaireLinks)
    .innerJoin(questionnaireVersions, eq(questionnaireVersions.id, questionnaireLinks.versionId))
    .innerJoin(questionnaires, eq(questionnaires.id, questionnaireVersions.questionnaireId))
    .innerJoin(studies, eq(studies.id, questionnaireLinks.studyId))
    .innerJoin(
      participants,
      and(eq(participants.id, questionnaireLinks.participantId), eq(participants.studyId, questionnaireLinks.studyId)),
    )
    .leftJoin(questionnaireResponses, eq(questionnaireResponses.linkId, questionnaireLinks.id))
    .where(eq(questionnaireLinks.tokenHash, hashToken(token)));
  if (!row)
    throw new TRPCError({
      code: "NOT_FOUND",
      message: "This questionnaire link is not valid. Please ask the researcher for a new one.",
    });
  // Withdrawing ends every link at once: nothing more is asked of them or stored.
  if (row.consentStatus === "withdrawn")
    throw new TRPCError({
      code: "FORBIDDEN",
      message: "This link no longer works: you have withdrawn from this study. Thank you for your time.",
    });
  if (row.link.usedAt)
    throw new TRPCError({
      code: "FORBIDDEN",
      message: "This questionnaire has already been submitted with this link. Thank you! A link can be used only once.",
    });
  if (row.link.expiresAt.getTime() < Date.now()) {
    throw new TRPCError({
      code: "FORBIDDEN",
      message: `This link expired at ${row.link.expiresAt.toISOString().slice(0, 16).replace("T", " ")} UTC. Please ask the researcher for a new one.`,
    });
  }
  const definition = row.definition as Definition;
  const settings = readSettings(row.settings);
  return {
    link: row.link,
    definition,
    // Each link draws its own order, the same on every reload.
    presented: presentedOrder(definition, row.link.id),
    name: row.name,
    version: row.version,
    // Participants see the study's neutral name, if it has one, and its own words beside the consent checkbox.
    studyTitle: shownTitle(row.studyTitle, settings, true),
    consentAgreement: settings.consentAgreement,
    participantCode: row.participantCode,
    answers: (row.response?.answers ?? {}) as Answers,
  };
}
