// Plugin repositories an administrator adds: synced over HTTP through the
// public loader, stored per plugin version (repository, robotId, version,
// content hash) with no more trust than the administrator gave the
// repository, and reported as what changed. A robot another source also
// provides is installed beside it, and the report says so in plain words.
// A robot the repository's index no longer lists is uninstalled (no longer
// offered; versions that pinned it run from plugin_documents), reported once
// with the experiments still using it; that is known only when every file of
// the index was read.
import { TRPCError } from "@trpc/server";
import { and, desc, eq, sql } from "drizzle-orm";
import { hashCanonical } from "@/core/protocol/canonical";
import {
  effectiveTrust,
  formatPluginError,
  pluginChanges,
  alsoProvided,
  chooseDocument,
  notSeenNotice,
  removedNotice,
  type Plugin,
  type PluginChange,
} from "@/core/plugins";
import { fetchRepository } from "@/robots/repository-sync";
import { audit } from "../audit";
import type { Database } from "@/store/client";
import { installedPlugins, pluginRepositories } from "@/store/schema";
import { pluginCatalog } from "@/robots/catalog";
import { experimentsUsing } from "./still-used";

export async function syncRepository(
  db: Database,
  repositoryId: string,
  actorId: string,
  fetchFn: typeof fetch = fetch,
) {
  const [repository] = await db.select().from(pluginRepositories).where(eq(pluginRepositories.id, repositoryId));
  if (!repository) throw new TRPCError({ code: "NOT_FOUND", message: "No such plugin repository." });
  const fetched = await fetchRepository(repository.url, fetchFn);
  const errors = fetched.errors.map(formatPluginError);
  let changes: PluginChange[] = [];
  // Not errors: what the administrator should know about what was installed.
  const notices: string[] = [];

  await db.transaction(async (tx) => {
    // One sync at a time decides which source is a robot's default: the first to install it.
    await tx.execute(sql`select pg_advisory_xact_lock(hashtext('hristudio.plugin-sync'))`);
    const { plugins: current } = await pluginCatalog(tx);
    const stored = await tx
      .select()
      .from(installedPlugins)
      .where(eq(installedPlugins.repositoryId, repositoryId))
      .orderBy(desc(installedPlugins.installedAt));
    const latest = new Map<string, Plugin>();
    for (const row of stored) if (!latest.has(row.robotId)) latest.set(row.robotId, row.definition as Plugin);
    const seen = new Set(fetched.plugins.map((f) => f.plugin.robotId));
    const gone = [...latest.keys()].filter((robotId) => !seen.has(robotId));
    // A file that could not be read may be the one that offers a robot not seen: nothing is known to be gone.
    const whole = fetched.index !== null && fetched.plugins.length === fetched.index.length;
    changes = pluginChanges(
      [...latest.values()],
      fetched.plugins.map((f) => f.plugin),
    ).filter((c) => whole || c.change !== "removed");
    const sourceName = `the repository "${fetched.repository?.name ?? repository.name}"`;
    if (!whole && gone.length) notices.push(notSeenNotice(gone));
    for (const robotId of whole ? gone : []) {
      const wasDefault = chooseDocument(current, robotId, null)?.source === repositoryId;
      notices.push(removedNotice(robotId, sourceName, await experimentsUsing(tx, repositoryId, robotId, wasDefault)));
      await tx
        .delete(installedPlugins)
        .where(and(eq(installedPlugins.repositoryId, repositoryId), eq(installedPlugins.robotId, robotId)));
    }
    for (const { plugin, trust } of fetched.plugins) {
      const hash = hashCanonical(plugin);
      const [same] = await tx
        .select()
        .from(installedPlugins)
        .where(
          and(
            eq(installedPlugins.repositoryId, repositoryId),
            eq(installedPlugins.robotId, plugin.robotId),
            eq(installedPlugins.version, plugin.version),
          ),
        );
      if (same && same.hash !== hash) {
        // A published version is immutable: experiments point at it.
        errors.push(
          `${plugin.robotId} ${plugin.version}: its content changed without a new version number; the stored ${plugin.version} is kept.`,
        );
        continue;
      }
      const notice = alsoProvided(
        {
          source: repositoryId,
          sourceName,
          robotId: plugin.robotId,
          version: plugin.version,
          hash,
        },
        current,
      );
      if (notice) notices.push(notice);
      // What the files claim (the lower of plugin and repository.json), capped by what the administrator chose.
      const trustLevel = effectiveTrust(repository.trust, trust);
      if (!same)
        await tx.insert(installedPlugins).values({
          repositoryId,
          robotId: plugin.robotId,
          version: plugin.version,
          name: plugin.name,
          trustLevel,
          definition: plugin,
          hash,
        });
    }
    // The repository's trust stays what the administrator chose: repository.json cannot raise it.
    await tx
      .update(pluginRepositories)
      .set({
        name: fetched.repository?.name ?? repository.name,
        lastSyncedAt: new Date(),
        lastSyncError: errors.length ? errors.join("\n") : null,
      })
      .where(eq(pluginRepositories.id, repositoryId));
    await audit(tx, {
      actorId,
      action: "plugins.sync",
      target: repositoryId,
      details: { changes: changes.filter((c) => c.change !== "unchanged"), errors, notices },
    });
  });
  return { changes, errors, notices };
}
