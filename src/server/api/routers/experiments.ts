import { TRPCError } from "@trpc/server";
import { asc, eq, sql } from "drizzle-orm";
import { z } from "zod";
import { actions, experimentVersions, experiments, steps } from "@/data/schema";
import { exportFile, importFile } from "../../experiments/exchange";
import { bumpRevision, loadDesign, renumberActions, renumberSteps, saveDesign } from "../../experiments/design";
import { qualified } from "@/data/qualified";
import { router, studyProcedure } from "../trpc";
import { id } from "../validation";
import { actionFields, designInput, experimentDetails, stepFields } from "./design-input";


/** Positions 0..n-1 in the given order; the order must name every row exactly once. */
function assertSameSet(given: string[], existing: string[], what: string) {
  if (given.length !== existing.length || new Set(given).size !== given.length || !given.every((g) => existing.includes(g))) {
    throw new TRPCError({ code: "BAD_REQUEST", message: `Please correct: order: must list every ${what} exactly once` });
  }
}

export const experimentsRouter = router({
  list: studyProcedure("experiment.read", "study", z.object({ studyId: id }))
    .query(({ ctx }) =>
      ctx.db
        .select({
          id: experiments.id,
          name: experiments.name,
          description: experiments.description,
          robotPluginId: experiments.robotPluginId,
          updatedAt: experiments.updatedAt,
          stepCount: sql<number>`(select count(*)::int from ${steps} where ${steps.experimentId} = ${qualified(experiments.id)})`,
          latestVersion: sql<number | null>`(select max(${experimentVersions.version}) from ${experimentVersions} where ${experimentVersions.experimentId} = ${qualified(experiments.id)})`,
        })
        .from(experiments)
        .where(eq(experiments.studyId, ctx.studyId))
        .orderBy(asc(experiments.name)),
    ),

  get: studyProcedure("experiment.read", "experiment", z.object({ experimentId: id }))
    .query(({ ctx }) => loadDesign(ctx.db, ctx.row.id)),

  create: studyProcedure("experiment.edit", "study", experimentDetails.extend({ studyId: id, description: experimentDetails.shape.description.default("") }))
    .mutation(async ({ ctx, input }) => {
      const [row] = await ctx.db.insert(experiments).values({ ...input, studyId: ctx.studyId, updatedBy: ctx.user.id }).returning();
      return row!;
    }),

  update: studyProcedure("experiment.edit", "experiment", experimentDetails.partial().extend({ experimentId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const { experimentId: _, ...changes } = input;
        const experimentId = ctx.row.id;
        await tx.update(experiments).set(changes).where(eq(experiments.id, experimentId));
        await bumpRevision(tx, experimentId, ctx.user.id);
        return loadDesign(tx, experimentId);
      }),
    ),

  delete: studyProcedure("experiment.edit", "experiment", z.object({ experimentId: id }))
    .mutation(async ({ ctx }) => {
      await ctx.db.delete(experiments).where(eq(experiments.id, ctx.row.id));
      return { deleted: ctx.row.id };
    }),

  /** The experiment as a file another lab can import. */
  exportFile: studyProcedure("experiment.read", "experiment", z.object({ experimentId: id }))
    .query(({ ctx }) => exportFile(ctx.db, ctx.row.id)),

  importFile: studyProcedure("experiment.edit", "study", z.object({ studyId: id, text: z.string().max(2_000_000, "the file must be smaller than 2 MB") }))
    .mutation(({ ctx, input }) => importFile(ctx.db, ctx.studyId, input.text, ctx.user.id)),

  /** The whole design in one transaction; refused if someone saved since `baseRevision`. */
  saveDesign: studyProcedure("experiment.edit", "experiment", designInput)
    .mutation(({ ctx, input }) => saveDesign(ctx.db, input, ctx.user.id)),

  createStep: studyProcedure("experiment.edit", "experiment", stepFields.extend({ experimentId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const experimentId = ctx.row.id;
        const [{ n }] = (await tx.select({ n: sql<number>`count(*)::int` }).from(steps).where(eq(steps.experimentId, experimentId))) as [{ n: number }];
        const [row] = await tx.insert(steps).values({ ...input, experimentId, position: n }).returning();
        await bumpRevision(tx, experimentId, ctx.user.id);
        return row!;
      }),
    ),

  updateStep: studyProcedure("experiment.edit", "step", stepFields.partial().extend({ stepId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const { stepId: _, ...changes } = input;
        const [row] = await tx.update(steps).set(changes).where(eq(steps.id, ctx.row.id)).returning();
        await bumpRevision(tx, row!.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  deleteStep: studyProcedure("experiment.edit", "step", z.object({ stepId: id }))
    .mutation(({ ctx }) =>
      ctx.db.transaction(async (tx) => {
        await tx.delete(steps).where(eq(steps.id, ctx.row.id));
        await renumberSteps(tx, ctx.row.experimentId);
        await bumpRevision(tx, ctx.row.experimentId, ctx.user.id);
        return { deleted: ctx.row.id };
      }),
    ),

  reorderSteps: studyProcedure("experiment.edit", "experiment", z.object({ experimentId: id, stepIds: z.array(id).max(500) }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const experimentId = ctx.row.id;
        const existing = await tx.select({ id: steps.id }).from(steps).where(eq(steps.experimentId, experimentId));
        assertSameSet(input.stepIds, existing.map((s) => s.id), "step");
        for (const [position, stepId] of input.stepIds.entries()) await tx.update(steps).set({ position }).where(eq(steps.id, stepId));
        await bumpRevision(tx, experimentId, ctx.user.id);
        return loadDesign(tx, experimentId);
      }),
    ),

  createAction: studyProcedure("experiment.edit", "step", actionFields.extend({ stepId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const step = ctx.row;
        const [{ n }] = (await tx.select({ n: sql<number>`count(*)::int` }).from(actions).where(eq(actions.stepId, step.id))) as [{ n: number }];
        const [row] = await tx.insert(actions).values({ ...input, stepId: step.id, position: n }).returning();
        await bumpRevision(tx, step.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  updateAction: studyProcedure("experiment.edit", "action", actionFields.partial().extend({ actionId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const { actionId: _, ...changes } = input;
        const [row] = await tx.update(actions).set(changes).where(eq(actions.id, ctx.row.id)).returning();
        await bumpRevision(tx, ctx.row.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  deleteAction: studyProcedure("experiment.edit", "action", z.object({ actionId: id }))
    .mutation(({ ctx }) =>
      ctx.db.transaction(async (tx) => {
        await tx.delete(actions).where(eq(actions.id, ctx.row.id));
        await renumberActions(tx, ctx.row.stepId);
        await bumpRevision(tx, ctx.row.experimentId, ctx.user.id);
        return { deleted: ctx.row.id };
      }),
    ),

  /** Moves an action to a position in a step of the same experiment (its own, or another). */
  moveAction: studyProcedure("experiment.edit", "action", z.object({ actionId: id, toStepId: id, toPosition: z.number().int().min(0) }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const action = ctx.row;
        const [from] = await tx.select().from(steps).where(eq(steps.id, action.stepId));
        const [to] = await tx.select().from(steps).where(eq(steps.id, input.toStepId));
        if (!to || to.experimentId !== from!.experimentId) {
          throw new TRPCError({ code: "BAD_REQUEST", message: "Please correct: toStepId: must be a step of the same experiment" });
        }
        const target = (await tx.select({ id: actions.id }).from(actions).where(eq(actions.stepId, to.id)).orderBy(asc(actions.position)))
          .map((a) => a.id)
          .filter((a) => a !== action.id);
        target.splice(Math.min(input.toPosition, target.length), 0, action.id);
        await tx.update(actions).set({ stepId: to.id }).where(eq(actions.id, action.id));
        for (const [position, actionId] of target.entries()) await tx.update(actions).set({ position }).where(eq(actions.id, actionId));
        if (from!.id !== to.id) await renumberActions(tx, from!.id);
        await bumpRevision(tx, to.experimentId, ctx.user.id);
        return loadDesign(tx, to.experimentId);
      }),
    ),
});
