import { TRPCError } from "@trpc/server";
import { z } from "zod";
import { portability } from "@/core/plugins";
import { loadDesign } from "../../experiments/design";
import { findPlugin, pluginCatalog } from "../../plugins/catalog";
import { guarded, router } from "../trpc";
import { id } from "../validation";

export const pluginsRouter = router({
  /** The robots an experiment can target, and the plugin files that could not be loaded, with why. */
  list: guarded("plugin.read").query(async () => {
    const { plugins, errors } = await pluginCatalog();
    return {
      robots: plugins.map((p) => ({ robotId: p.robotId, name: p.name, version: p.version, trustLevel: p.trustLevel ?? "community", transport: p.transport ?? "rosbridge", capabilities: p.capabilities ?? [] })),
      problems: errors.map((e) => `${e.file} ${e.path}: ${e.reason}`),
    };
  }),

  /** Which actions of an experiment's draft a robot can run: before the trial, not during it. */
  portability: guarded("experiment.read")
    .input(z.object({ experimentId: id, robotId: z.string().max(200).optional() }))
    .query(async ({ ctx, input }) => {
      const design = await loadDesign(ctx.db, input.experimentId);
      const robotId = input.robotId ?? design.robotPluginId;
      const plugin = await findPlugin(robotId);
      if (!plugin) throw new TRPCError({ code: "NOT_FOUND", message: `No robot plugin called "${robotId}" is installed.` });
      return portability(design, plugin);
    }),
});
