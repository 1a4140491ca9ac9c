// Whether a participant may take part in a trial now: consent recorded (unless
// the study turned that check off), and never after withdrawing.
import { TRPCError } from "@trpc/server";
import { and, eq } from "drizzle-orm";
import { readSettings } from "@/core/studies/settings";
import type { Database } from "@/store/client";
import { participants, studies } from "@/store/schema";

export async function assertMayTakePart(db: Database, participantId: string, studyId: string) {
  const [p] = await db
    .select()
    .from(participants)
    .where(and(eq(participants.id, participantId), eq(participants.studyId, studyId)));
  if (!p)
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: "Please correct: participantId: not a participant of this study",
    });
  if (p.consentStatus === "withdrawn") {
    throw new TRPCError({
      code: "PRECONDITION_FAILED",
      message: `${p.code} has withdrawn from the study and cannot take part in another trial.`,
    });
  }
  const [study] = await db.select({ settings: studies.settings }).from(studies).where(eq(studies.id, studyId));
  if (readSettings(study!.settings).requireConsent && p.consentStatus !== "given") {
    throw new TRPCError({
      code: "PRECONDITION_FAILED",
      message: `${p.code} has no recorded consent (${p.consentStatus}). Record their consent first, or turn off the consent check in the study's overview.`,
    });
  }
  return p;
}
