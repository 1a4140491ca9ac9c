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
import { participants, questionnaireLinks, questionnaireVersions, questionnaires, trials } from "@/store/schema";
import { insertQuestionnaire } from "../../questionnaires/create";
import { hashToken, newToken } from "../../questionnaires/links";
import { submitted } from "../../questionnaires/responses";
import { qualified } from "@/store/qualified";
import { router, studyProcedure } from "../trpc";
import { id, text } from "../validation";

function checkedDefinition(definition: unknown): Definition {
  const parsed = definitionSchema.safeParse(definition);
  if (parsed.success) return parsed.data;
  const issue = parsed.error.issues[0]!;
  throw new TRPCError({
    code: "BAD_REQUEST",
    message: `Please correct: definition.${issue.path.join(".")}: ${issue.message}`,
  });
}

export const questionnairesRouter = router({
  list: studyProcedure("trial.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: questionnaires.id,
        name: questionnaires.name,
        timing: questionnaires.timing,
        instrument: sql<string | null>`${questionnaires.draft}->>'instrument'`,
        latestVersion: sql<
          number | null
        >`(select max(${questionnaireVersions.version}) from ${questionnaireVersions} where ${questionnaireVersions.questionnaireId} = ${qualified(questionnaires.id)})`,
      })
      .from(questionnaires)
      .where(eq(questionnaires.studyId, ctx.studyId))
      .orderBy(asc(questionnaires.name)),
  ),

  get: studyProcedure("trial.read", "questionnaire", z.object({ questionnaireId: id })).query(({ ctx }) => ({
    ...ctx.row,
    draft: ctx.row.draft as Definition,
  })),

  create: studyProcedure(
    "experiment.edit",
    "study",
    z.object({
      studyId: id,
      name: text("Name", 200).optional(),
      instrument: z.enum(INSTRUMENTS).nullable().default(null),
    }),
  ).mutation(async ({ ctx, input }) => {
    const draft = input.instrument
      ? instrumentDefinition(input.instrument)
      : blankQuestionnaire(input.name ?? "New questionnaire", () => crypto.randomUUID());
    return insertQuestionnaire(ctx.db, ctx.studyId, { name: input.name ?? draft.title, draft });
  }),

  save: studyProcedure(
    "experiment.edit",
    "questionnaire",
    z.object({
      questionnaireId: id,
      name: text("Name", 200).optional(),
      timing: z.enum(["before", "after", "none"]).optional(),
      definition: z.unknown().optional(),
    }),
  ).mutation(async ({ ctx, input }) => {
    const draft = input.definition === undefined ? undefined : checkedDefinition(input.definition);
    await ctx.db
      .update(questionnaires)
      .set({ name: input.name, timing: input.timing, draft, updatedAt: new Date() })
      .where(eq(questionnaires.id, ctx.row.id));
    return { saved: ctx.row.id };
  }),

  /** Freezes the draft as a numbered version: answers always point at the exact version shown. */
  publish: studyProcedure("version.publish", "questionnaire", z.object({ questionnaireId: id })).mutation(({ ctx }) =>
    ctx.db.transaction(async (tx) => {
      const [q] = await tx.select().from(questionnaires).where(eq(questionnaires.id, ctx.row.id)).for("update");
      const definition = checkedDefinition(q!.draft);
      if (items(definition).length === 0)
        throw new TRPCError({
          code: "BAD_REQUEST",
          message: "This questionnaire has no questions yet: add at least one before publishing.",
        });
      const [{ next }] = (await tx
        .select({ next: sql<number>`coalesce(max(${questionnaireVersions.version}), 0)::int + 1` })
        .from(questionnaireVersions)
        .where(eq(questionnaireVersions.questionnaireId, q!.id))) as [{ next: number }];
      const [version] = await tx
        .insert(questionnaireVersions)
        .values({
          questionnaireId: q!.id,
          version: next,
          definition,
          hash: hashCanonical(definition),
          publishedBy: ctx.user.id,
        })
        .returning({
          id: questionnaireVersions.id,
          version: questionnaireVersions.version,
          hash: questionnaireVersions.hash,
        });
      return version!;
    }),
  ),

  /** A one-time link for one participant (and trial) to fill in the latest version, on a tablet or sent ahead. */
  createLink: studyProcedure(
    "trial.run",
    "questionnaire",
    z.object({
      questionnaireId: id,
      participantId: id,
      trialId: id.nullable().default(null),
      expiresInMinutes: z
        .number()
        .int()
        .min(1)
        .max(60 * 24 * 30)
        .default(120),
    }),
  ).mutation(async ({ ctx, input }) => {
    // Both ids are this study's (the middleware checked); the trial must also be this participant's.
    const q = ctx.row;
    const [p] = await ctx.db.select().from(participants).where(eq(participants.id, input.participantId));
    if (p!.consentStatus === "withdrawn")
      throw new TRPCError({
        code: "PRECONDITION_FAILED",
        message: `${p!.code} has withdrawn from the study: they are sent no more questionnaires.`,
      });
    if (input.trialId) {
      const [t] = await ctx.db.select().from(trials).where(eq(trials.id, input.trialId));
      if (t!.participantId !== p!.id)
        throw new TRPCError({
          code: "BAD_REQUEST",
          message: "Please correct: trialId: this trial is not this participant's",
        });
    }
    const [version] = await ctx.db
      .select()
      .from(questionnaireVersions)
      .where(eq(questionnaireVersions.questionnaireId, q.id))
      .orderBy(desc(questionnaireVersions.version))
      .limit(1);
    if (!version)
      throw new TRPCError({
        code: "PRECONDITION_FAILED",
        message: `“${q.name}” is not published yet: publish it before handing it to participants.`,
      });
    const token = newToken();
    const expiresAt = new Date(Date.now() + input.expiresInMinutes * 60_000);
    await ctx.db.insert(questionnaireLinks).values({
      tokenHash: hashToken(token),
      studyId: q.studyId,
      versionId: version.id,
      participantId: p!.id,
      trialId: input.trialId,
      expiresAt,
      createdBy: ctx.user.id,
    });
    return { path: `/q/${token}`, token, expiresAt, version: version.version };
  }),

  /** What a trial's participant answered, with scores: for its analysis page. */
  responses: studyProcedure("data.read", "trial", z.object({ trialId: id })).query(({ ctx }) =>
    submitted(ctx.db, eq(questionnaireLinks.trialId, ctx.row.id)),
  ),

  /** Every submitted answer of the study: one row per participant × item, plus the scores. */
  exportCsv: studyProcedure("data.read", "study", z.object({ studyId: id })).query(async ({ ctx }) => ({
    filename: "questionnaire-answers.csv",
    contentType: "text/csv; charset=utf-8",
    body: answersCsv(await submitted(ctx.db, eq(questionnaireLinks.studyId, ctx.studyId))),
  })),
});
