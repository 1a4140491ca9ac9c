import { TRPCError } from "@trpc/server";
import { asc, eq } from "drizzle-orm";
import { z } from "zod";
import { chooseDocument, FIRST_PARTY } from "@/core/plugins";
import { audit } from "../../audit";
import { pluginRepositories } from "@/store/schema";
import { findPlugin, pluginCatalog } from "@/robots/catalog";
import { syncRepository } from "../../plugins/repositories";
import { guarded, router } from "../trpc";
import { id } from "../validation";

// The administrator's choice when adding a repository: the most any of its plugins is trusted.
const trust = z.enum(["official", "verified", "community"], { error: "must be official, verified or community" });

const repositoryUrl = z
  .url({ protocol: /^https?$/, error: "must be an http:// or https:// address" })
  .max(2000, "must be at most 2000 characters");

export const pluginsRouter = router({
  /**
   * The plugin documents an experiment can target, every source's current
   * one of each robot (several sources may offer one robotId; `isDefault` marks
   * the one an experiment that has not chosen runs), the plugin files that
   * could not be loaded (with why), and the ways to a robot this server's
   * settings open.
   */
  list: guarded("plugin.read").query(async ({ ctx }) => {
    const { plugins, problems } = await pluginCatalog(ctx.db);
    return {
      robots: plugins.map(({ plugin: p, trust, source, sourceName, hash }) => ({
        robotId: p.robotId,
        name: p.name,
        version: p.version,
        trustLevel: trust,
        source: source === FIRST_PARTY ? ("first-party" as const) : ("repository" as const),
        // FIRST_PARTY or the repository's id: what an experiment records as its choice.
        sourceId: source,
        sourceName,
        hash,
        isDefault: chooseDocument(plugins, p.robotId, null)?.source === source,
        transport: p.transport ?? "rosbridge",
        capabilities: p.capabilities ?? [],
      })),
      problems,
      channels: ctx.robotChannels,
    };
  }),

  /**
   * One robot's whole plugin, from `source` (an experiment's choice) or, with
   * none, the default source: the designer's library lists its actions with their forms.
   */
  get: guarded("plugin.read")
    .input(z.object({ robotId: z.string().max(200), source: z.string().max(200).nullable().default(null) }))
    .query(async ({ ctx, input }) => {
      const plugin = await findPlugin(ctx.db, input.robotId, input.source);
      if (!plugin)
        throw new TRPCError({
          code: "NOT_FOUND",
          message: input.source
            ? `No robot plugin called "${input.robotId}" is installed from the source this experiment chose; choose another in the designer.`
            : `No robot plugin called "${input.robotId}" is installed.`,
        });
      return plugin;
    }),

  repositories: router({
    list: guarded("admin.plugins").query(({ ctx }) =>
      // A removed repository is kept (published experiments point at its plugins) but no longer listed.
      ctx.db
        .select()
        .from(pluginRepositories)
        .where(eq(pluginRepositories.enabled, true))
        .orderBy(asc(pluginRepositories.name)),
    ),

    add: guarded("admin.plugins")
      .input(z.object({ url: repositoryUrl, trust: trust.default("community") }))
      .mutation(async ({ ctx, input }) => {
        const [row] = await ctx.db
          .insert(pluginRepositories)
          .values({ url: input.url, name: input.url, trust: input.trust, createdBy: ctx.user.id })
          // Adding a removed repository again brings it back, with the trust chosen now.
          .onConflictDoUpdate({
            target: pluginRepositories.url,
            set: { enabled: true, trust: input.trust },
            setWhere: eq(pluginRepositories.enabled, false),
          })
          .returning();
        if (!row) throw new TRPCError({ code: "CONFLICT", message: "That repository is already added." });
        await audit(ctx.db, {
          actorId: ctx.user.id,
          action: "plugins.repository.add",
          target: row.id,
          details: { url: input.url, trust: input.trust },
        });
        return row;
      }),

    remove: guarded("admin.plugins")
      .input(z.object({ repositoryId: id }))
      .mutation(async ({ ctx, input }) => {
        // Installed versions stay: published experiments point at them.
        await ctx.db
          .update(pluginRepositories)
          .set({ enabled: false })
          .where(eq(pluginRepositories.id, input.repositoryId));
        await audit(ctx.db, { actorId: ctx.user.id, action: "plugins.repository.remove", target: input.repositoryId });
        return { removed: input.repositoryId };
      }),

    sync: guarded("admin.plugins")
      .input(z.object({ repositoryId: id }))
      .mutation(({ ctx, input }) => syncRepository(ctx.db, input.repositoryId, ctx.user.id)),
  }),
});
