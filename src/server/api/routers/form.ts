// The participant's side of a questionnaire: no account, only the one-time
// link's token. Answers are kept as a draft on every change, so a reload or a
// dropped connection loses nothing; submitting closes the link.
import { TRPCError } from "@trpc/server";
import { and, eq, isNull, ne } from "drizzle-orm";
import { z } from "zod";
import { answerProblems, consentGiven, scoreAnswers, type Answers } from "@/core/questionnaires/answers";
import { audit } from "../../audit";
import { participants, questionnaireLinks, questionnaireResponses } from "@/store/schema";
import { openLink } from "../../questionnaires/links";
import { publicProcedure, router } from "../trpc";

const token = z.string().min(10).max(200);
const answers = z.record(
  z.string().max(100),
  z.union([z.number(), z.string().max(10_000), z.array(z.string().max(200)).max(30), z.boolean()]),
);

function refuse(problems: string[]): never {
  throw new TRPCError({ code: "BAD_REQUEST", message: `Please check: ${problems.join("; ")}` });
}

export const formRouter = router({
  open: publicProcedure.input(z.object({ token })).query(async ({ ctx, input }) => {
    const open = await openLink(ctx.db, input.token);
    return {
      name: open.name,
      version: open.version,
      studyTitle: open.studyTitle,
      consentAgreement: open.consentAgreement,
      participantCode: open.participantCode,
      definition: open.presented,
      answers: open.answers,
      expiresAt: open.link.expiresAt,
    };
  }),

  save: publicProcedure.input(z.object({ token, answers })).mutation(async ({ ctx, input }) => {
    const open = await openLink(ctx.db, input.token);
    const problems = answerProblems(open.definition, input.answers as Answers, false);
    if (problems.length) refuse(problems);
    await ctx.db
      .insert(questionnaireResponses)
      .values({ linkId: open.link.id, answers: input.answers })
      .onConflictDoUpdate({
        target: questionnaireResponses.linkId,
        set: { answers: input.answers, updatedAt: new Date() },
      });
    return { savedAt: new Date() };
  }),

  submit: publicProcedure.input(z.object({ token, answers })).mutation(async ({ ctx, input }) => {
    const open = await openLink(ctx.db, input.token);
    const given = input.answers as Answers;
    const problems = answerProblems(open.definition, given, true);
    if (problems.length) refuse(problems);
    const scored = scoreAnswers(open.definition, given);
    const score = scored?.ok ? { score: scored.score, subscales: scored.subscales } : null;
    const consent = consentGiven(open.definition, given);
    return ctx.db.transaction(async (tx) => {
      // Only one submission wins, even if two arrive together.
      const [closed] = await tx
        .update(questionnaireLinks)
        .set({ usedAt: new Date() })
        .where(and(eq(questionnaireLinks.id, open.link.id), isNull(questionnaireLinks.usedAt)))
        .returning({ id: questionnaireLinks.id });
      if (!closed)
        throw new TRPCError({
          code: "FORBIDDEN",
          message:
            "This questionnaire has already been submitted with this link. Thank you! A link can be used only once.",
        });
      const submitted = {
        answers: given,
        status: "submitted" as const,
        score,
        submittedAt: new Date(),
        updatedAt: new Date(),
      };
      await tx
        .insert(questionnaireResponses)
        .values({ linkId: open.link.id, ...submitted })
        .onConflictDoUpdate({ target: questionnaireResponses.linkId, set: submitted });
      // A digital consent is the participant's consent record: who, when, which text.
      if (consent !== null) {
        const consentVersion = `${open.name} v${open.version}`;
        // Never over a withdrawal, even one recorded while this form was open.
        const [changed] = await tx
          .update(participants)
          .set(
            consent
              ? { consentStatus: "given", consentDate: new Date(), consentVersion }
              : { consentStatus: "declined", consentDate: new Date() },
          )
          .where(and(eq(participants.id, open.link.participantId), ne(participants.consentStatus, "withdrawn")))
          .returning({ id: participants.id });
        if (!changed)
          throw new TRPCError({
            code: "FORBIDDEN",
            message: "This link no longer works: you have withdrawn from this study. Thank you for your time.",
          });
        await audit(tx, {
          actorId: null,
          studyId: open.link.studyId,
          action: `participant.consent.${consent ? "given" : "declined"}`,
          target: open.link.participantId,
          details: { code: open.participantCode, consentVersion, by: "participant, digital form" },
        });
      }
      return { submitted: true, score: score?.score ?? null };
    });
  }),
});
