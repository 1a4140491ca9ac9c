// The robot plugins this server knows: first-party files from plugins/
// (through the public loader, like any other) and plugins synced from enabled
// repositories into the database. Each robotId has one source: first-party
// first, then the repository that installed it first (see chooseProviders).
import { asc, eq, and, type SQL } from "drizzle-orm";
import { join } from "node:path";
import { hashCanonical } from "@/core/protocol/canonical";
import { chooseProviders, FIRST_PARTY, type Plugin, type TrustLevel } from "@/core/plugins";
import { loadPluginFolder, type PluginFolder } from "@/robots/plugin-folder";
import type { Database } from "@/store/client";
import { installedPlugins, pluginRepositories } from "@/store/schema";

export const PLUGINS_DIR = join(process.cwd(), "plugins");
const FIRST_PARTY_NAME = "the first-party plugins";

let loading: Promise<PluginFolder> | null = null;

export function firstPartyPlugins(): Promise<PluginFolder> {
  loading ??= loadPluginFolder(PLUGINS_DIR);
  return loading;
}

/** One plugin version with its identity: source, robotId, version and content hash. */
export interface KnownPlugin {
  plugin: Plugin;
  robotId: string;
  trust: TrustLevel;
  /** FIRST_PARTY or the repository's id. */
  source: string;
  sourceName: string;
  /** SHA-256 of the plugin's canonical JSON. */
  hash: string;
}

type Reader = Pick<Database, "select">;

// The first-party files never change while the server runs: hashed once, not on every catalogue read.
let firstPartyKnown: KnownPlugin[] | null = null;

async function known(db: Reader, where?: SQL): Promise<{ versions: KnownPlugin[]; folder: PluginFolder }> {
  const folder = await firstPartyPlugins();
  firstPartyKnown ??= folder.plugins.map(
    (p): KnownPlugin => ({
      plugin: p,
      robotId: p.robotId,
      trust: p.trustLevel ?? "official",
      source: FIRST_PARTY,
      sourceName: FIRST_PARTY_NAME,
      hash: hashCanonical(p),
    }),
  );
  const firstParty = firstPartyKnown;
  // Oldest install first: the first repository to install a robot keeps it.
  const rows = await db
    .select({ row: installedPlugins, repositoryName: pluginRepositories.name })
    .from(installedPlugins)
    .innerJoin(pluginRepositories, eq(pluginRepositories.id, installedPlugins.repositoryId))
    .where(and(eq(pluginRepositories.enabled, true), where))
    .orderBy(asc(installedPlugins.installedAt));
  const synced = rows.map(
    ({ row, repositoryName }): KnownPlugin => ({
      plugin: row.definition as Plugin,
      robotId: row.robotId,
      trust: row.trustLevel as TrustLevel,
      source: row.repositoryId!,
      sourceName: `the repository "${repositoryName}"`,
      hash: row.hash,
    }),
  );
  return { versions: [...firstParty, ...synced], folder };
}

/** Every robot, with the version it runs with, and the first-party files that could not be loaded. */
export async function pluginCatalog(db: Reader): Promise<{ plugins: KnownPlugin[]; problems: string[] }> {
  const { versions, folder } = await known(db);
  return { plugins: chooseProviders(versions), problems: folder.errors.map((e) => `${e.file} ${e.path}: ${e.reason}`) };
}

/** The plugin a robotId runs with today, with its identity. */
export async function knownPlugin(db: Reader, robotId: string): Promise<KnownPlugin | undefined> {
  const { versions } = await known(db, eq(installedPlugins.robotId, robotId));
  return chooseProviders(versions.filter((v) => v.robotId === robotId))[0];
}

export async function findPlugin(db: Reader, robotId: string): Promise<Plugin | undefined> {
  return (await knownPlugin(db, robotId))?.plugin;
}
