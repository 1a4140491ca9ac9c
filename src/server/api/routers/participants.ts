import { TRPCError } from "@trpc/server";
import { asc, eq, sql } from "drizzle-orm";
import { z } from "zod";
import { audit } from "../../audit";
import { demographicProblems, type Answers } from "@/core/studies/demographics";
import { readSettings } from "@/core/studies/settings";
import type { Database } from "@/store/client";
import { participants, studies, trials } from "@/store/schema";
import { qualified } from "@/store/qualified";
import { router, studyProcedure } from "../trpc";
import { id, text } from "../validation";

const CONSENT = ["pending", "given", "declined", "withdrawn"] as const;
const fields = {
  consentStatus: z.enum(CONSENT, { error: `must be one of ${CONSENT.join(", ")}` }),
  consentDate: z.coerce.date({ error: "must be a date" }).nullable(),
  consentVersion: z.string().trim().min(1).max(50).nullable(),
  notes: z.string().max(5000, "must be at most 5000 characters"),
  demographics: z.record(z.string().max(40), z.union([z.string().max(1000), z.number()]), {
    error: "must be answers by field",
  }),
};

/** Demographic answers must fit the study's fields; consent given records the consent document's version. */
async function checked<T extends { demographics?: Answers; consentStatus?: string; consentVersion?: string | null }>(
  db: Database,
  studyId: string,
  changes: T,
): Promise<T> {
  const [study] = await db.select({ settings: studies.settings }).from(studies).where(eq(studies.id, studyId));
  const settings = readSettings(study!.settings);
  if (changes.demographics) {
    const problems = demographicProblems(settings.demographics, changes.demographics);
    if (problems.length)
      throw new TRPCError({ code: "BAD_REQUEST", message: `Please correct: demographics: ${problems.join("; ")}` });
  }
  if (changes.consentStatus === "given" && !changes.consentVersion)
    return { ...changes, consentVersion: settings.consentDocumentVersion };
  return changes;
}
const code = text("Participant code", 50).regex(
  /^[\w.-]+$/,
  "Participant code may use letters, digits, '.', '_' and '-' only (no names)",
);

function duplicateCode(error: unknown, value: string): never {
  if (
    (error as { code?: string }).code === "23505" ||
    (error as { cause?: { code?: string } }).cause?.code === "23505"
  ) {
    throw new TRPCError({ code: "CONFLICT", message: `Participant code ${value} is already used in this study.` });
  }
  throw error;
}

export const participantsRouter = router({
  list: studyProcedure("participant.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: participants.id,
        code: participants.code,
        consentStatus: participants.consentStatus,
        consentDate: participants.consentDate,
        consentVersion: participants.consentVersion,
        notes: participants.notes,
        demographics: participants.demographics,
        // A blinded wizard sees who comes, never in which condition.
        conditionId: ctx.blinding.conditionsHidden ? sql<string | null>`null` : participants.conditionId,
        // The group a stratified assignment balanced them in, as their answer was then.
        stratum: sql<string | null>`${participants.assignment}->>'stratum'`,
        trialCount: sql<number>`(select count(*)::int from ${trials} where ${trials.participantId} = ${qualified(participants.id)})`,
      })
      .from(participants)
      .where(eq(participants.studyId, ctx.studyId))
      .orderBy(asc(participants.code)),
  ),

  create: studyProcedure(
    "participant.manage",
    "study",
    z.object({
      studyId: id,
      code,
      consentStatus: fields.consentStatus.default("pending"),
      consentDate: fields.consentDate.default(null),
      consentVersion: fields.consentVersion.default(null),
      notes: fields.notes.default(""),
      demographics: fields.demographics.default({}),
    }),
  ).mutation(async ({ ctx, input }) => {
    const [row] = await ctx.db
      .insert(participants)
      .values(await checked(ctx.db, ctx.studyId, { ...input, studyId: ctx.studyId }))
      .returning()
      .catch((e: unknown) => duplicateCode(e, input.code));
    return row!;
  }),

  update: studyProcedure(
    "participant.manage",
    "participant",
    z.object({
      participantId: id,
      code: code.optional(),
      consentStatus: fields.consentStatus.optional(),
      consentDate: fields.consentDate.optional(),
      consentVersion: fields.consentVersion.optional(),
      notes: fields.notes.optional(),
      demographics: fields.demographics.optional(),
    }),
  ).mutation(async ({ ctx, input }) => {
    const { participantId: _, ...given } = input;
    const participantId = ctx.row.id;
    // A withdrawal stands: only the owner's explicit reinstatement (below) can undo it.
    if (ctx.row.consentStatus === "withdrawn" && given.consentStatus && given.consentStatus !== "withdrawn") {
      throw new TRPCError({
        code: "FORBIDDEN",
        message: `${ctx.row.code} withdrew from the study. Only the study's owner can reinstate them, with a reason that is recorded.`,
      });
    }
    const changes = await checked(ctx.db, ctx.studyId, given);
    return ctx.db.transaction(async (tx) => {
      const [row] = await tx
        .update(participants)
        .set(changes)
        .where(eq(participants.id, participantId))
        .returning()
        .catch((e: unknown) => duplicateCode(e, input.code ?? ""));
      // Consent changes are part of the study's record: who changed it, and when.
      if (changes.consentStatus) {
        await audit(tx, {
          actorId: ctx.user.id,
          studyId: row!.studyId,
          action: `participant.consent.${changes.consentStatus}`,
          target: participantId,
          details: { code: row!.code, consentVersion: row!.consentVersion },
        });
      }
      return row!;
    });
  }),

  /** The owner undoes a withdrawal (e.g. recorded by mistake): consent given again now, with the reason in the audit log. */
  reinstate: studyProcedure(
    "participant.reinstate",
    "participant",
    z.object({ participantId: id, reason: text("Reason", 1000) }),
  ).mutation(({ ctx, input }) =>
    ctx.db.transaction(async (tx) => {
      if (ctx.row.consentStatus !== "withdrawn")
        throw new TRPCError({
          code: "PRECONDITION_FAILED",
          message: `${ctx.row.code} has not withdrawn: there is nothing to reinstate.`,
        });
      const [study] = await tx.select({ settings: studies.settings }).from(studies).where(eq(studies.id, ctx.studyId));
      const consentVersion = readSettings(study!.settings).consentDocumentVersion;
      const [row] = await tx
        .update(participants)
        .set({ consentStatus: "given", consentDate: new Date(), consentVersion })
        .where(eq(participants.id, ctx.row.id))
        .returning();
      await audit(tx, {
        actorId: ctx.user.id,
        studyId: ctx.studyId,
        action: "participant.consent.reinstated",
        target: ctx.row.id,
        details: { code: ctx.row.code, reason: input.reason, consentVersion },
      });
      return row!;
    }),
  ),
});
