// A study's questionnaires: built and versioned like experiments, attached to
// sessions before or after the trial, filled in through one-time links, and
// exported with every answer and score.
import { TRPCError } from "@trpc/server";
import { asc, desc, eq, sql } from "drizzle-orm";
import { z } from "zod";
import { hashCanonical } from "@/core/protocol/canonical";
import { blankQuestionnaire } from "@/core/questionnaires/builder";
import { definitionSchema, INSTRUMENTS, items, type Definition } from "@/core/questionnaires/definition";
import { instrumentDefinition } from "@/core/questionnaires/instruments";
import { answersCsv } from "@/core/questionnaires/export";
import { participants, questionnaireLinks, questionnaireVersions, questionnaires, trials } from "../../db/schema";
import { hashToken, newToken } from "../../questionnaires/links";
import { submitted } from "../../questionnaires/responses";
import { qualified } from "../../db/qualified";
import { guarded, router } from "../trpc";
import { id, text } from "../validation";

function checkedDefinition(definition: unknown): Definition {
  const parsed = definitionSchema.safeParse(definition);
  if (parsed.success) return parsed.data;
  const issue = parsed.error.issues[0]!;
  throw new TRPCError({ code: "BAD_REQUEST", message: `Please correct: definition.${issue.path.join(".")}: ${issue.message}` });
}

export const questionnairesRouter = router({
  list: guarded("trial.read")
    .input(z.object({ studyId: id }))
    .query(({ ctx, input }) =>
      ctx.db
        .select({
          id: questionnaires.id,
          name: questionnaires.name,
          timing: questionnaires.timing,
          instrument: sql<string | null>`${questionnaires.draft}->>'instrument'`,
          latestVersion: sql<number | null>`(select max(${questionnaireVersions.version}) from ${questionnaireVersions} where ${questionnaireVersions.questionnaireId} = ${qualified(questionnaires.id)})`,
        })
        .from(questionnaires)
        .where(eq(questionnaires.studyId, input.studyId))
        .orderBy(asc(questionnaires.name)),
    ),

  get: guarded("trial.read")
    .input(z.object({ questionnaireId: id }))
    .query(async ({ ctx, input }) => {
      const [row] = await ctx.db.select().from(questionnaires).where(eq(questionnaires.id, input.questionnaireId));
      return { ...row!, draft: row!.draft as Definition };
    }),

  create: guarded("experiment.edit")
    .input(z.object({ studyId: id, name: text("Name", 200).optional(), instrument: z.enum(INSTRUMENTS).nullable().default(null) }))
    .mutation(async ({ ctx, input }) => {
      const draft = input.instrument ? instrumentDefinition(input.instrument) : blankQuestionnaire(input.name ?? "New questionnaire", () => crypto.randomUUID());
      const [row] = await ctx.db
        .insert(questionnaires)
        .values({ studyId: input.studyId, name: input.name ?? draft.title, draft })
        .returning({ id: questionnaires.id });
      return row!;
    }),

  save: guarded("experiment.edit")
    .input(z.object({ questionnaireId: id, name: text("Name", 200).optional(), timing: z.enum(["before", "after", "none"]).optional(), definition: z.unknown().optional() }))
    .mutation(async ({ ctx, input }) => {
      const draft = input.definition === undefined ? undefined : checkedDefinition(input.definition);
      await ctx.db
        .update(questionnaires)
        .set({ name: input.name, timing: input.timing, draft, updatedAt: new Date() })
        .where(eq(questionnaires.id, input.questionnaireId));
      return { saved: input.questionnaireId };
    }),

  /** Freezes the draft as a numbered version: answers always point at the exact version shown. */
  publish: guarded("version.publish")
    .input(z.object({ questionnaireId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [q] = await tx.select().from(questionnaires).where(eq(questionnaires.id, input.questionnaireId)).for("update");
        const definition = checkedDefinition(q!.draft);
        if (items(definition).length === 0) throw new TRPCError({ code: "BAD_REQUEST", message: "This questionnaire has no questions yet: add at least one before publishing." });
        const [{ next }] = (await tx
          .select({ next: sql<number>`coalesce(max(${questionnaireVersions.version}), 0)::int + 1` })
          .from(questionnaireVersions)
          .where(eq(questionnaireVersions.questionnaireId, q!.id))) as [{ next: number }];
        const [version] = await tx
          .insert(questionnaireVersions)
          .values({ questionnaireId: q!.id, version: next, definition, hash: hashCanonical(definition), publishedBy: ctx.user.id })
          .returning({ id: questionnaireVersions.id, version: questionnaireVersions.version, hash: questionnaireVersions.hash });
        return version!;
      }),
    ),

  /** A one-time link for one participant (and trial) to fill in the latest version, on a tablet or sent ahead. */
  createLink: guarded("trial.run")
    .input(z.object({ questionnaireId: id, participantId: z.string().max(100), trialId: z.string().max(100).nullable().default(null), expiresInMinutes: z.number().int().min(1).max(60 * 24 * 30).default(120) }))
    .mutation(async ({ ctx, input }) => {
      const [q] = await ctx.db.select().from(questionnaires).where(eq(questionnaires.id, input.questionnaireId));
      const [p] = await ctx.db.select().from(participants).where(eq(participants.id, input.participantId));
      if (!p || p.studyId !== q!.studyId) throw new TRPCError({ code: "BAD_REQUEST", message: "Please correct: participantId: this participant is not in the questionnaire's study" });
      if (input.trialId) {
        const [t] = await ctx.db.select().from(trials).where(eq(trials.id, input.trialId));
        if (!t || t.studyId !== q!.studyId || t.participantId !== p.id) throw new TRPCError({ code: "BAD_REQUEST", message: "Please correct: trialId: this trial is not this participant's, in this study" });
      }
      const [version] = await ctx.db.select().from(questionnaireVersions).where(eq(questionnaireVersions.questionnaireId, q!.id)).orderBy(desc(questionnaireVersions.version)).limit(1);
      if (!version) throw new TRPCError({ code: "PRECONDITION_FAILED", message: `“${q!.name}” is not published yet: publish it before handing it to participants.` });
      const token = newToken();
      const expiresAt = new Date(Date.now() + input.expiresInMinutes * 60_000);
      await ctx.db.insert(questionnaireLinks).values({ tokenHash: hashToken(token), studyId: q!.studyId, versionId: version.id, participantId: p.id, trialId: input.trialId, expiresAt, createdBy: ctx.user.id });
      return { path: `/q/${token}`, token, expiresAt, version: version.version };
    }),

  /** What a trial's participant answered, with scores: for its analysis page. */
  responses: guarded("data.read")
    .input(z.object({ trialId: id }))
    .query(({ ctx, input }) => submitted(ctx.db, eq(questionnaireLinks.trialId, input.trialId))),

  /** Every submitted answer of the study: one row per participant × item, plus the scores. */
  exportCsv: guarded("data.read")
    .input(z.object({ studyId: id }))
    .query(async ({ ctx, input }) => ({
      filename: "questionnaire-answers.csv",
      contentType: "text/csv; charset=utf-8",
      body: answersCsv(await submitted(ctx.db, eq(questionnaireLinks.studyId, input.studyId))),
    })),
});
