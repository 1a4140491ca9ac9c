import { TRPCError } from "@trpc/server";
import { asc, eq, sql } from "drizzle-orm";
import { z } from "zod";
import { actions, experimentVersions, experiments, steps } from "../../db/schema";
import { exportFile, importFile } from "../../experiments/exchange";
import { bumpRevision, loadDesign, renumberActions, renumberSteps, saveDesign } from "../../experiments/design";
import { qualified } from "../../db/qualified";
import { guarded, router } from "../trpc";
import { id } from "../validation";
import { actionFields, designInput, experimentDetails, stepFields } from "./design-input";


/** Positions 0..n-1 in the given order; the order must name every row exactly once. */
function assertSameSet(given: string[], existing: string[], what: string) {
  if (given.length !== existing.length || new Set(given).size !== given.length || !given.every((g) => existing.includes(g))) {
    throw new TRPCError({ code: "BAD_REQUEST", message: `Please correct: order: must list every ${what} exactly once` });
  }
}

export const experimentsRouter = router({
  list: guarded("experiment.read")
    .input(z.object({ studyId: id }))
    .query(({ ctx, input }) =>
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
        .where(eq(experiments.studyId, input.studyId))
        .orderBy(asc(experiments.name)),
    ),

  get: guarded("experiment.read")
    .input(z.object({ experimentId: id }))
    .query(({ ctx, input }) => loadDesign(ctx.db, input.experimentId)),

  create: guarded("experiment.edit")
    .input(experimentDetails.extend({ studyId: id, description: experimentDetails.shape.description.default("") }))
    .mutation(async ({ ctx, input }) => {
      const [row] = await ctx.db.insert(experiments).values({ ...input, updatedBy: ctx.user.id }).returning();
      return row!;
    }),

  update: guarded("experiment.edit")
    .input(experimentDetails.partial().extend({ experimentId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const { experimentId, ...changes } = input;
        await tx.update(experiments).set(changes).where(eq(experiments.id, experimentId));
        await bumpRevision(tx, experimentId, ctx.user.id);
        return loadDesign(tx, experimentId);
      }),
    ),

  delete: guarded("experiment.edit")
    .input(z.object({ experimentId: id }))
    .mutation(async ({ ctx, input }) => {
      await ctx.db.delete(experiments).where(eq(experiments.id, input.experimentId));
      return { deleted: input.experimentId };
    }),

  /** The experiment as a file another lab can import. */
  exportFile: guarded("experiment.read")
    .input(z.object({ experimentId: id }))
    .query(({ ctx, input }) => exportFile(ctx.db, input.experimentId)),

  importFile: guarded("experiment.edit")
    .input(z.object({ studyId: id, text: z.string().max(2_000_000, "the file must be smaller than 2 MB") }))
    .mutation(({ ctx, input }) => importFile(ctx.db, input.studyId, input.text, ctx.user.id)),

  /** The whole design in one transaction; refused if someone saved since `baseRevision`. */
  saveDesign: guarded("experiment.edit")
    .input(designInput)
    .mutation(({ ctx, input }) => saveDesign(ctx.db, input, ctx.user.id)),

  createStep: guarded("experiment.edit")
    .input(stepFields.extend({ experimentId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [{ n }] = (await tx.select({ n: sql<number>`count(*)::int` }).from(steps).where(eq(steps.experimentId, input.experimentId))) as [{ n: number }];
        const [row] = await tx.insert(steps).values({ ...input, position: n }).returning();
        await bumpRevision(tx, input.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  updateStep: guarded("experiment.edit")
    .input(stepFields.partial().extend({ stepId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const { stepId, ...changes } = input;
        const [row] = await tx.update(steps).set(changes).where(eq(steps.id, stepId)).returning();
        await bumpRevision(tx, row!.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  deleteStep: guarded("experiment.edit")
    .input(z.object({ stepId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [row] = await tx.delete(steps).where(eq(steps.id, input.stepId)).returning();
        await renumberSteps(tx, row!.experimentId);
        await bumpRevision(tx, row!.experimentId, ctx.user.id);
        return { deleted: input.stepId };
      }),
    ),

  reorderSteps: guarded("experiment.edit")
    .input(z.object({ experimentId: id, order: z.array(id).max(500) }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const existing = await tx.select({ id: steps.id }).from(steps).where(eq(steps.experimentId, input.experimentId));
        assertSameSet(input.order, existing.map((s) => s.id), "step");
        for (const [position, stepId] of input.order.entries()) await tx.update(steps).set({ position }).where(eq(steps.id, stepId));
        await bumpRevision(tx, input.experimentId, ctx.user.id);
        return loadDesign(tx, input.experimentId);
      }),
    ),

  createAction: guarded("experiment.edit")
    .input(actionFields.extend({ stepId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [{ n }] = (await tx.select({ n: sql<number>`count(*)::int` }).from(actions).where(eq(actions.stepId, input.stepId))) as [{ n: number }];
        const [row] = await tx.insert(actions).values({ ...input, position: n }).returning();
        const [step] = await tx.select().from(steps).where(eq(steps.id, input.stepId));
        await bumpRevision(tx, step!.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  updateAction: guarded("experiment.edit")
    .input(actionFields.partial().extend({ actionId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const { actionId, ...changes } = input;
        const [row] = await tx.update(actions).set(changes).where(eq(actions.id, actionId)).returning();
        const [step] = await tx.select().from(steps).where(eq(steps.id, row!.stepId));
        await bumpRevision(tx, step!.experimentId, ctx.user.id);
        return row!;
      }),
    ),

  deleteAction: guarded("experiment.edit")
    .input(z.object({ actionId: id }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [row] = await tx.delete(actions).where(eq(actions.id, input.actionId)).returning();
        const [step] = await tx.select().from(steps).where(eq(steps.id, row!.stepId));
        await renumberActions(tx, row!.stepId);
        await bumpRevision(tx, step!.experimentId, ctx.user.id);
        return { deleted: input.actionId };
      }),
    ),

  /** Moves an action to a position in a step of the same experiment (its own, or another). */
  moveAction: guarded("experiment.edit")
    .input(z.object({ actionId: id, toStepId: id, toPosition: z.number().int().min(0) }))
    .mutation(({ ctx, input }) =>
      ctx.db.transaction(async (tx) => {
        const [action] = await tx.select().from(actions).where(eq(actions.id, input.actionId));
        const [from] = await tx.select().from(steps).where(eq(steps.id, action!.stepId));
        const [to] = await tx.select().from(steps).where(eq(steps.id, input.toStepId));
        if (!to || to.experimentId !== from!.experimentId) {
          throw new TRPCError({ code: "BAD_REQUEST", message: "Please correct: toStepId: must be a step of the same experiment" });
        }
        const target = (await tx.select({ id: actions.id }).from(actions).where(eq(actions.stepId, to.id)).orderBy(asc(actions.position)))
          .map((a) => a.id)
          .filter((a) => a !== action!.id);
        target.splice(Math.min(input.toPosition, target.length), 0, action!.id);
        await tx.update(actions).set({ stepId: to.id }).where(eq(actions.id, action!.id));
        for (const [position, actionId] of target.entries()) await tx.update(actions).set({ position }).where(eq(actions.id, actionId));
        if (from!.id !== to.id) await renumberActions(tx, from!.id);
        await bumpRevision(tx, to.experimentId, ctx.user.id);
        return loadDesign(tx, to.experimentId);
      }),
    ),
});
