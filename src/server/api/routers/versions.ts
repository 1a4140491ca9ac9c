import { TRPCError } from "@trpc/server";
import { desc, eq } from "drizzle-orm";
import { diffProtocols } from "@/core/designer/diff";
import type { ProtocolSnapshot } from "@/core/protocol/snapshot";
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
          pluginHash: experimentVersions.pluginHash,
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

  /** What changed from one version to another, in sentences. */
  diff: guarded("experiment.read")
    .input(z.object({ experimentId: id, from: z.number().int().min(1), to: z.number().int().min(1) }))
    .query(async ({ ctx, input }) => {
      const rows = await ctx.db
        .select({ version: experimentVersions.version, snapshot: experimentVersions.snapshot, experimentId: experimentVersions.experimentId })
        .from(experimentVersions)
        .where(eq(experimentVersions.experimentId, input.experimentId));
      const pick = (n: number) => {
        const row = rows.find((r) => r.version === n);
        if (!row) throw new TRPCError({ code: "NOT_FOUND", message: `This experiment has no version ${n}.` });
        return row.snapshot as ProtocolSnapshot;
      };
      return diffProtocols(pick(input.from), pick(input.to));
    }),
});
