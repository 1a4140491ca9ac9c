import { randomBytes } from "node:crypto";
import { TRPCError } from "@trpc/server";
import { and, desc, eq, isNotNull, sql } from "drizzle-orm";
import { z } from "zod";
import { decide, studyRoleMay } from "@/core/access/policy";
import { byConditionCsv } from "@/core/analysis/by-condition";
import { STUDY_STATUSES } from "@/core/studies/status";
import {
  changedSettings,
  readSettings,
  settingsProblems,
  shownTitle,
  studySettingsChangeSchema,
  type StudySettings,
} from "@/core/studies/settings";
import { type Blinding, blindingFor } from "@/core/studies/blinding";
import type { Database } from "@/store/client";
import { audit } from "../../audit";
import { studyArchive } from "../../studies/archive";
import { createStudy } from "../../studies/create";
import { studyFromTemplate } from "../../studies/template";
import { studyMethodsText } from "../../studies/methods";
import { studyFigures, studyResultsByCondition } from "../../studies/summary";
import { experiments, participants, studies, studyMembers, trials } from "@/store/schema";
import { qualified } from "@/store/qualified";
import { fileAnswer } from "../file-answer";
import { guarded, router, studyProcedure } from "../trpc";
import { id, text } from "../validation";

/** Which blinds this change lifts: turned off, or (results) ended by completing the study. */
function liftedBlinds(before: StudySettings, after: StudySettings, statusBefore: string, statusAfter: string) {
  const ended = (s: string) => s === "completed" || s === "archived";
  const lifted: string[] = [];
  if (before.blinding.conditionsFromWizards && !after.blinding.conditionsFromWizards) lifted.push("conditions");
  if (before.blinding.conditionsFromObservers && !after.blinding.conditionsFromObservers)
    lifted.push("conditions.observers");
  const resultsBefore = before.blinding.resultsUntilComplete && !ended(statusBefore);
  const resultsAfter = after.blinding.resultsUntilComplete && !ended(statusAfter);
  if (resultsBefore && !resultsAfter) lifted.push("results");
  return lifted;
}

/**
 * A study as a caller blind to its conditions sees it: the neutral name, and
 * no description (a study's title and description often state its hypothesis).
 */
function neutral<T extends { title: string; description: string }>(
  study: T,
  settings: StudySettings,
  blinding: Blinding,
): T {
  if (!blinding.conditionsHidden) return study;
  return { ...study, title: shownTitle(study.title, settings, true), description: "" };
}

/** A seed of the team's own is set before the first assignment: a later one would rewrite the order already used. */
async function seedProblems(db: Database, studyId: string): Promise<string[]> {
  const [{ assigned }] = (await db
    .select({ assigned: sql<number>`count(*)::int` })
    .from(participants)
    .where(and(eq(participants.studyId, studyId), isNotNull(participants.assignment)))) as [{ assigned: number }];
  return assigned === 0
    ? []
    : [
        `assignment.seed: the seed can only be set before the first assignment (${assigned} participant${assigned === 1 ? " is" : "s are"} assigned already)`,
      ];
}

export const studiesRouter = router({
  /** The studies I am a member of, with my role: nobody sees any other. */
  mine: guarded("account.read").query(async ({ ctx }) => {
    const rows = await ctx.db
      .select({
        settings: studies.settings,
        id: studies.id,
        title: studies.title,
        description: studies.description,
        status: studies.status,
        role: studyMembers.role,
        updatedAt: studies.updatedAt,
        experimentCount: sql<number>`(select count(*)::int from ${experiments} where ${experiments.studyId} = ${qualified(studies.id)})`,
        trialCount: sql<number>`(select count(*)::int from ${trials} where ${trials.studyId} = ${qualified(studies.id)})`,
        participantCount: sql<number>`(select count(*)::int from ${participants} where ${participants.studyId} = ${qualified(studies.id)})`,
      })
      .from(studies)
      .innerJoin(studyMembers, and(eq(studyMembers.studyId, studies.id), eq(studyMembers.userId, ctx.user.id)))
      .orderBy(desc(studies.updatedAt));
    return rows.map(({ settings, ...row }) =>
      neutral(row, readSettings(settings), blindingFor(row.role, readSettings(settings), row.status)),
    );
  }),

  get: studyProcedure("study.read", "study", z.object({ studyId: id })).query(({ ctx }) => {
    const { studyId: _, ...study } = ctx.row;
    const settings = readSettings(study.settings);
    // The seed lets anyone recompute who gets which condition next: only those who design the study see it.
    const seeSeed = studyRoleMay(ctx.studyRole, "experiment.edit");
    return {
      ...neutral(study, settings, ctx.blinding),
      settings: seeSeed ? settings : { ...settings, assignment: { ...settings.assignment, seed: undefined } },
      myRole: ctx.studyRole,
    };
  }),

  create: guarded("study.create")
    .input(z.object({ title: text("Title", 200), description: z.string().max(5000).default("") }))
    .mutation(async ({ ctx, input }) => {
      return ctx.db.transaction((tx) => createStudy(tx, ctx.user.id, input));
    }),

  /**
   * A new study from this one as a template: its design (settings that are
   * design, experiments, conditions, questionnaires), never its participants
   * or data; the caller becomes its owner and only member. Reading the
   * template's design is checked on the template study (the middleware);
   * creating a study, on the caller's account, as for a blank study.
   */
  createFromTemplate: studyProcedure(
    "experiment.read",
    "study",
    z.object({ studyId: id, title: text("Title", 200), description: z.string().max(5000).optional() }),
  ).mutation(({ ctx, input }) => {
    const mayCreate = decide({ systemRole: ctx.user.role, studyRole: null, viaToken: !!ctx.token }, "study.create");
    if (!mayCreate.allow) throw new TRPCError({ code: "FORBIDDEN", message: mayCreate.reason });
    return studyFromTemplate(ctx.db, ctx.row.id, ctx.user.id, { title: input.title, description: input.description });
  }),

  update: studyProcedure(
    "study.update",
    "study",
    z.object({
      studyId: id,
      title: text("Title", 200).optional(),
      description: z.string().max(5000).optional(),
      status: z.enum(STUDY_STATUSES).optional(),
      settings: studySettingsChangeSchema.optional(),
    }),
  ).mutation(async ({ ctx, input }) => {
    const { studyId: _, settings, ...rest } = input;
    const studyId = ctx.row.id;
    const current = ctx.row;
    const before = readSettings(current.settings);
    // The seed is the server's, made once per choice of strategy, so assignments can be audited and reproduced.
    const merged = settings ? changedSettings(before, settings, () => randomBytes(12).toString("hex")) : null;
    const problems = merged ? settingsProblems(merged) : [];
    const seed = settings?.assignment?.seed;
    if (seed !== undefined && seed !== before.assignment.seed) problems.push(...(await seedProblems(ctx.db, studyId)));
    if (problems.length > 0) throw new TRPCError({ code: "BAD_REQUEST", message: problems.join("; ") });
    const changes = merged ? { ...rest, settings: merged } : rest;
    return ctx.db.transaction(async (tx) => {
      const [study] = await tx
        .update(studies)
        .set({ ...changes, updatedAt: new Date() })
        .where(eq(studies.id, studyId))
        .returning();
      await audit(tx, { actorId: ctx.user.id, studyId, action: "study.update", target: studyId, details: changes });
      for (const lifted of liftedBlinds(before, merged ?? before, current.status, study!.status)) {
        await audit(tx, { actorId: ctx.user.id, studyId, action: `study.blind.lifted.${lifted}`, target: studyId });
      }
      return study!;
    });
  }),

  /** Fidelity across the study's finished trials: the table, each step's timing, the consistency. */
  figures: studyProcedure("data.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    studyFigures(ctx.db, ctx.studyId),
  ),

  /** Each measure compared across conditions: n, mean, SD, median and range. */
  resultsByCondition: studyProcedure("data.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    studyResultsByCondition(ctx.db, ctx.studyId),
  ),

  /** The same as a tidy CSV (one row per condition and measure), for R or a spreadsheet. */
  resultsByConditionCsv: studyProcedure("data.read", "study", z.object({ studyId: id })).query(async ({ ctx }) => ({
    filename: "results-by-condition.csv",
    contentType: "text/csv; charset=utf-8",
    body: byConditionCsv(await studyResultsByCondition(ctx.db, ctx.studyId)),
  })),

  /** The whole study described for a paper's methods section, from its data as it stands, as Markdown and plain text. */
  methods: studyProcedure("data.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    studyMethodsText(ctx.db, ctx.studyId),
  ),

  /** Everything of the study as one zip, for the lab's archive or a paper's data. */
  exportArchive: studyProcedure("data.read", "study", z.object({ studyId: id })).query(async ({ ctx }) =>
    fileAnswer(ctx, await studyArchive(ctx.db, ctx.studyId)),
  ),

  delete: studyProcedure(
    "study.delete",
    "study",
    z.object({ studyId: id, confirmTitle: z.string().max(200) }),
  ).mutation(async ({ ctx, input }) => {
    if (ctx.row.title !== input.confirmTitle) {
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: "Please correct: confirmTitle: type the study's exact title to delete it",
      });
    }
    await ctx.db.delete(studies).where(eq(studies.id, ctx.row.id));
    return { deleted: ctx.row.id };
  }),
});
