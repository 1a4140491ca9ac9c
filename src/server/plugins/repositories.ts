// Plugin repositories an administrator adds: synced over HTTP through the
// public loader, stored per plugin version with the trust the repository
// earns, and reported as what changed.
import { TRPCError } from "@trpc/server";
import { and, desc, eq } from "drizzle-orm";
import { hashCanonical } from "@/core/protocol/canonical";
import { formatPluginError, pluginChanges, type Plugin } from "@/core/plugins";
import { fetchRepository } from "@/robots/repository-sync";
import { audit } from "../audit";
import type { Database } from "../db/client";
import { installedPlugins, pluginRepositories } from "../db/schema";

export async function syncRepository(db: Database, repositoryId: string, actorId: string, fetchFn: typeof fetch = fetch) {
  const [repository] = await db.select().from(pluginRepositories).where(eq(pluginRepositories.id, repositoryId));
  if (!repository) throw new TRPCError({ code: "NOT_FOUND", message: "No such plugin repository." });
  const fetched = await fetchRepository(repository.url, fetchFn);
  const errors = fetched.errors.map(formatPluginError);
  const stored = await db.select().from(installedPlugins).where(eq(installedPlugins.repositoryId, repositoryId)).orderBy(desc(installedPlugins.installedAt));
  const latest = new Map<string, Plugin>();
  for (const row of stored) if (!latest.has(row.robotId)) latest.set(row.robotId, row.definition as Plugin);
  const changes = pluginChanges([...latest.values()], fetched.plugins.map((f) => f.plugin));

  await db.transaction(async (tx) => {
    for (const { plugin, trust } of fetched.plugins) {
      const hash = hashCanonical(plugin);
      const [same] = await tx.select().from(installedPlugins).where(and(eq(installedPlugins.robotId, plugin.robotId), eq(installedPlugins.version, plugin.version)));
      if (same && same.hash !== hash) {
        // A published version is immutable: experiments point at it.
        errors.push(`${plugin.robotId} ${plugin.version}: its content changed without a new version number; the stored ${plugin.version} is kept.`);
        continue;
      }
      if (!same) await tx.insert(installedPlugins).values({ repositoryId, robotId: plugin.robotId, version: plugin.version, name: plugin.name, trustLevel: trust, definition: plugin, hash });
    }
    await tx
      .update(pluginRepositories)
      .set({ name: fetched.repository?.name ?? repository.name, trust: fetched.repository?.trust ?? repository.trust, lastSyncedAt: new Date(), lastSyncError: errors.length ? errors.join("\n") : null })
      .where(eq(pluginRepositories.id, repositoryId));
    await audit(tx, { actorId, action: "plugins.sync", target: repositoryId, details: { changes: changes.filter((c) => c.change !== "unchanged"), errors } });
  });
  return { changes, errors };
}
