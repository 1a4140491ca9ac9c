import { asc, eq, sql } from "drizzle-orm";
import { TRPCError } from "@trpc/server";
import { z } from "zod";
import { studyAccessOf } from "@/store/study-access";
import { experimentVersions, experiments, steps } from "@/store/schema";
import { duplicate, exportFile, importFile } from "../../experiments/exchange";
import { loadDesign, saveDesign } from "../../experiments/design";
import { qualified } from "@/store/qualified";
import { knownPlugin } from "@/robots/catalog";
import { authorize, router, studyProcedure } from "../trpc";
import { id } from "../validation";
import { designInput, experimentDetails } from "./design-input";

export const experimentsRouter = router({
  list: studyProcedure("experiment.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: experiments.id,
        name: experiments.name,
        description: experiments.description,
        robotId: experiments.robotId,
        updatedAt: experiments.updatedAt,
        stepCount: sql<number>`(select count(*)::int from ${steps} where ${steps.experimentId} = ${qualified(experiments.id)})`,
        latestVersion: sql<
          number | null
        >`(select max(${experimentVersions.version}) from ${experimentVersions} where ${experimentVersions.experimentId} = ${qualified(experiments.id)})`,
      })
      .from(experiments)
      .where(eq(experiments.studyId, ctx.studyId))
      .orderBy(asc(experiments.name)),
  ),

  get: studyProcedure("experiment.read", "experiment", z.object({ experimentId: id })).query(({ ctx }) =>
    loadDesign(ctx.db, ctx.row.id),
  ),

  create: studyProcedure(
    "experiment.edit",
    "study",
    experimentDetails.extend({ studyId: id, description: experimentDetails.shape.description.default("") }),
  ).mutation(async ({ ctx, input }) => {
    const [row] = await ctx.db
      .insert(experiments)
      .values({ ...input, studyId: ctx.studyId, updatedBy: ctx.user.id })
      .returning();
    return row!;
  }),

  /**
   * Which source's document of its robot the experiment runs, when several
   * sources offer it: "first-party" or a repository's id, or null for the
   * default. Its next published version pins that document.
   */
  choosePlugin: studyProcedure(
    "experiment.edit",
    "experiment",
    z.object({ experimentId: id, source: z.string().max(200).nullable() }),
  ).mutation(async ({ ctx, input }) => {
    const chosen = await knownPlugin(ctx.db, ctx.row.robotId, input.source);
    if (!chosen)
      throw new TRPCError({
        code: "BAD_REQUEST",
        message: `That source does not provide the robot "${ctx.row.robotId}": choose one of the plugin documents listed for it.`,
      });
    await ctx.db
      .update(experiments)
      .set({ pluginSource: input.source, updatedAt: new Date(), updatedBy: ctx.user.id })
      .where(eq(experiments.id, ctx.row.id));
    return { source: chosen.source, sourceName: chosen.sourceName, version: chosen.version, hash: chosen.hash };
  }),

  /** The experiment as a file another lab can import. */
  exportFile: studyProcedure("experiment.read", "experiment", z.object({ experimentId: id })).query(({ ctx }) =>
    exportFile(ctx.db, ctx.row.id),
  ),

  importFile: studyProcedure(
    "experiment.edit",
    "study",
    z.object({ studyId: id, text: z.string().max(2_000_000, "the file must be smaller than 2 MB") }),
  ).mutation(({ ctx, input }) => importFile(ctx.db, ctx.studyId, input.text, ctx.user.id)),

  /**
   * A copy of the draft, the design only (never its versions or trials): in
   * its own study, or in `intoStudyId`. Reading the source is checked on the
   * source experiment's own study (the middleware); designing on the study it
   * goes into, which is the only id taken from the caller for that side.
   */
  duplicate: studyProcedure(
    "experiment.read",
    "experiment",
    z.object({ experimentId: id, intoStudyId: id.optional() }),
  ).mutation(async ({ ctx, input }) => {
    const into = await authorize(
      ctx.db,
      ctx.user,
      "experiment.edit",
      "study",
      input.intoStudyId ?? ctx.studyId,
      ctx.token,
    ).catch(async (error: unknown) => {
      if (!(error instanceof TRPCError) || error.code !== "FORBIDDEN" || !input.intoStudyId) throw error;
      // The policy's words say "this study": here there are two, so name which and why.
      const { role } = await studyAccessOf(ctx.db, input.intoStudyId, ctx.user.id);
      throw new TRPCError({
        code: "FORBIDDEN",
        message: `Not copied: in the study you chose to copy into you are ${role === "observer" ? "an" : "a"} ${role}, and only its owner and researchers design there.`,
      });
    });
    return duplicate(ctx.db, ctx.row.id, ctx.user.id, into.studyId);
  }),

  /** The whole design in one transaction; refused if someone saved since `baseRevision`. */
  saveDesign: studyProcedure("experiment.edit", "experiment", designInput).mutation(({ ctx, input }) =>
    saveDesign(ctx.db, input, ctx.user.id),
  ),
});
