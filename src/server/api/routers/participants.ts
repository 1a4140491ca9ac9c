import { TRPCError } from "@trpc/server";
import { asc, eq, sql } from "drizzle-orm";
import { z } from "zod";
import { audit } from "../../audit";
import { participants, trials } from "../../db/schema";
import { guarded, router } from "../trpc";
import { id, text } from "../validation";

const CONSENT = ["pending", "given", "declined", "withdrawn"] as const;
const fields = {
  consentStatus: z.enum(CONSENT, { error: `must be one of ${CONSENT.join(", ")}` }),
  consentDate: z.coerce.date({ error: "must be a date" }).nullable(),
  notes: z.string().max(5000, "must be at most 5000 characters"),
};
const code = text("Participant code", 50).regex(/^[\w.-]+$/, "Participant code may use letters, digits, '.', '_' and '-' only (no names)");

function duplicateCode(error: unknown, value: string): never {
  if ((error as { code?: string }).code === "23505" || (error as { cause?: { code?: string } }).cause?.code === "23505") {
    throw new TRPCError({ code: "CONFLICT", message: `Participant code ${value} is already used in this study.` });
  }
  throw error;
}

export const participantsRouter = router({
  list: guarded("participant.read")
    .input(z.object({ studyId: id }))
    .query(({ ctx, input }) =>
      ctx.db
        .select({
          id: participants.id,
          code: participants.code,
          consentStatus: participants.consentStatus,
          consentDate: participants.consentDate,
          notes: participants.notes,
          conditionId: participants.conditionId,
          trialCount: sql<number>`(select count(*)::int from ${trials} where ${trials.participantId} = ${participants.id})`,
        })
        .from(participants)
        .where(eq(participants.studyId, input.studyId))
        .orderBy(asc(participants.code)),
    ),

  create: guarded("participant.manage")
    .input(z.object({ studyId: id, code, consentStatus: fields.consentStatus.default("pending"), consentDate: fields.consentDate.default(null), notes: fields.notes.default("") }))
    .mutation(async ({ ctx, input }) => {
      const [row] = await ctx.db
        .insert(participants)
        .values(input)
        .returning()
        .catch((e: unknown) => duplicateCode(e, input.code));
      return row!;
    }),

  update: guarded("participant.manage")
    .input(z.object({ participantId: id, code: code.optional(), consentStatus: fields.consentStatus.optional(), consentDate: fields.consentDate.optional(), notes: fields.notes.optional() }))
    .mutation(async ({ ctx, input }) => {
      const { participantId, ...changes } = input;
      return ctx.db.transaction(async (tx) => {
        const [row] = await tx
          .update(participants)
          .set(changes)
          .where(eq(participants.id, participantId))
          .returning()
          .catch((e: unknown) => duplicateCode(e, input.code ?? ""));
        // Consent changes are part of the study's record: who changed it, and when.
        if (changes.consentStatus) {
          await audit(tx, { actorId: ctx.user.id, studyId: row!.studyId, action: `participant.consent.${changes.consentStatus}`, target: participantId, details: { code: row!.code } });
        }
        return row!;
      });
    }),

  delete: guarded("participant.manage")
    .input(z.object({ participantId: id }))
    .mutation(async ({ ctx, input }) => {
      const used = await ctx.db.select({ id: trials.id }).from(trials).where(eq(trials.participantId, input.participantId)).limit(1);
      if (used.length) throw new TRPCError({ code: "BAD_REQUEST", message: "This participant has trials; their data must be kept. Mark them withdrawn instead." });
      await ctx.db.delete(participants).where(eq(participants.id, input.participantId));
      return { deleted: input.participantId };
    }),
});
