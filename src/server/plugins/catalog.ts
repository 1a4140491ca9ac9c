// The robot plugins this server knows: first-party files from plugins/
// (through the public loader, like any other) and plugins synced from
// repositories into the database. First-party wins on a shared robotId.
import { desc, eq } from "drizzle-orm";
import { join } from "node:path";
import type { Plugin, TrustLevel } from "@/core/plugins";
import { loadPluginFolder, type PluginFolder } from "@/robots/plugin-folder";
import type { Database } from "../db/client";
import { installedPlugins } from "../db/schema";

export const PLUGINS_DIR = join(process.cwd(), "plugins");

let loading: Promise<PluginFolder> | null = null;

export function firstPartyPlugins(): Promise<PluginFolder> {
  loading ??= loadPluginFolder(PLUGINS_DIR);
  return loading;
}

export interface KnownPlugin {
  plugin: Plugin;
  trust: TrustLevel;
  source: "first-party" | "repository";
}

/** Every robot, its newest version only. */
export async function pluginCatalog(db: Database): Promise<{ plugins: KnownPlugin[]; problems: string[] }> {
  const folder = await firstPartyPlugins();
  const known = new Map<string, KnownPlugin>(folder.plugins.map((p) => [p.robotId, { plugin: p, trust: p.trustLevel ?? "official", source: "first-party" }]));
  const synced = await db.select().from(installedPlugins).orderBy(desc(installedPlugins.installedAt));
  for (const row of synced) {
    if (!known.has(row.robotId)) known.set(row.robotId, { plugin: row.definition as Plugin, trust: row.trustLevel as TrustLevel, source: "repository" });
  }
  return { plugins: [...known.values()], problems: folder.errors.map((e) => `${e.file} ${e.path}: ${e.reason}`) };
}

export async function findPlugin(db: Database, robotId: string): Promise<Plugin | undefined> {
  const first = (await firstPartyPlugins()).plugins.find((p) => p.robotId === robotId);
  if (first) return first;
  const [row] = await db.select().from(installedPlugins).where(eq(installedPlugins.robotId, robotId)).orderBy(desc(installedPlugins.installedAt)).limit(1);
  return row?.definition as Plugin | undefined;
}
