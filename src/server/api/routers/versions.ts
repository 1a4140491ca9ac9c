import { TRPCError } from "@trpc/server";
import { desc, eq } from "drizzle-orm";
import { diffProtocols } from "@/core/designer/diff";
import { z } from "zod";
import { experimentVersions, user } from "@/store/schema";
import { methodsText } from "../../experiments/methods";
import { publish } from "../../experiments/publish";
import { router, studyProcedure } from "../trpc";
import { id } from "../validation";

export const versionsRouter = router({
  publish: studyProcedure("version.publish", "experiment", z.object({ experimentId: id })).mutation(({ ctx }) =>
    publish(ctx.db, ctx.row.id, ctx.user.id),
  ),

  list: studyProcedure("experiment.read", "experiment", z.object({ experimentId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: experimentVersions.id,
        version: experimentVersions.version,
        hash: experimentVersions.hash,
        robotId: experimentVersions.robotId,
        pluginVersion: experimentVersions.pluginVersion,
        pluginHash: experimentVersions.pluginHash,
        pluginSource: experimentVersions.pluginSource,
        publishedAt: experimentVersions.publishedAt,
        publishedBy: user.name,
      })
      .from(experimentVersions)
      .leftJoin(user, eq(user.id, experimentVersions.publishedBy))
      .where(eq(experimentVersions.experimentId, ctx.row.id))
      .orderBy(desc(experimentVersions.version)),
  ),

  get: studyProcedure("experiment.read", "version", z.object({ versionId: id })).query(({ ctx }) => {
    const { studyId: _, ...version } = ctx.row;
    return version;
  }),

  /** The version described for a paper's methods section, as Markdown and as plain text. */
  methods: studyProcedure("experiment.read", "version", z.object({ versionId: id })).query(({ ctx }) => {
    const { studyId, ...version } = ctx.row;
    return methodsText(ctx.db, version, studyId);
  }),

  /** What changed from one version to another, in sentences. */
  diff: studyProcedure(
    "experiment.read",
    "experiment",
    z.object({ experimentId: id, from: z.number().int().min(1), to: z.number().int().min(1) }),
  ).query(async ({ ctx, input }) => {
    const rows = await ctx.db
      .select({
        version: experimentVersions.version,
        snapshot: experimentVersions.snapshot,
        experimentId: experimentVersions.experimentId,
      })
      .from(experimentVersions)
      .where(eq(experimentVersions.experimentId, ctx.row.id));
    const pick = (n: number) => {
      const row = rows.find((r) => r.version === n);
      if (!row) throw new TRPCError({ code: "NOT_FOUND", message: `This experiment has no version ${n}.` });
      return row.snapshot;
    };
    return diffProtocols(pick(input.from), pick(input.to));
  }),
});
