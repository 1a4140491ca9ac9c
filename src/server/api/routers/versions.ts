import { desc, eq } from "drizzle-orm";
import { z } from "zod";
import { experimentVersions, user } from "../../db/schema";
import { publish } from "../../experiments/publish";
import { guarded, router } from "../trpc";
import { id } from "../validation";

export const versionsRouter = router({
  publish: guarded("version.publish")
    .input(z.object({ experimentId: id }))
    .mutation(({ ctx, input }) => publish(ctx.db, input.experimentId, ctx.user.id)),

  list: guarded("experiment.read")
    .input(z.object({ experimentId: id }))
    .query(({ ctx, input }) =>
      ctx.db
        .select({
          id: experimentVersions.id,
          version: experimentVersions.version,
          hash: experimentVersions.hash,
          pluginId: experimentVersions.pluginId,
          pluginVersion: experimentVersions.pluginVersion,
          publishedAt: experimentVersions.publishedAt,
          publishedBy: user.name,
        })
        .from(experimentVersions)
        .leftJoin(user, eq(user.id, experimentVersions.publishedBy))
        .where(eq(experimentVersions.experimentId, input.experimentId))
        .orderBy(desc(experimentVersions.version)),
    ),

  get: guarded("experiment.read")
    .input(z.object({ versionId: id }))
    .query(async ({ ctx, input }) => {
      const [row] = await ctx.db.select().from(experimentVersions).where(eq(experimentVersions.id, input.versionId));
      return row!;
    }),
});
