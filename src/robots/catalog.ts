// The robot plugins this server knows: first-party files from plugins/
// (through the public loader, like any other) and plugins synced from enabled
// repositories into the database. Several sources may offer one robotId: each
// keeps its own document, and an experiment runs the one of the source it chose
// (see latestPerSource and chooseDocument).
import { asc, eq, and, type SQL } from "drizzle-orm";
import { join } from "node:path";
import { hashCanonical } from "@/core/protocol/canonical";
import {
  chooseDocument,
  FIRST_PARTY,
  latestPerSource,
  type Plugin,
  type ProvidedPlugin,
  type TrustLevel,
} from "@/core/plugins";
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
export interface KnownPlugin extends ProvidedPlugin {
  plugin: Plugin;
  trust: TrustLevel;
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
      version: p.version,
      trust: p.trustLevel ?? "official",
      source: FIRST_PARTY,
      sourceName: FIRST_PARTY_NAME,
      hash: hashCanonical(p),
    }),
  );
  const firstParty = firstPartyKnown;
  // Oldest install first: an experiment that has not chosen runs the first repository's document of its robot.
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
      version: row.version,
      trust: row.trustLevel as TrustLevel,
      source: row.repositoryId!,
      sourceName: `the repository "${repositoryName}"`,
      hash: row.hash,
    }),
  );
  return { versions: [...firstParty, ...synced], folder };
}

/**
 * Every source's current document of every robot, the default one of a robot
 * first, and the first-party files that could not be loaded.
 */
export async function pluginCatalog(db: Reader): Promise<{ plugins: KnownPlugin[]; problems: string[] }> {
  const { versions, folder } = await known(db);
  return { plugins: latestPerSource(versions), problems: folder.errors.map((e) => `${e.file} ${e.path}: ${e.reason}`) };
}

/** The document an experiment for `robotId` runs today: `source`'s, or with null the default. */
export async function knownPlugin(
  db: Reader,
  robotId: string,
  source: string | null,
): Promise<KnownPlugin | undefined> {
  const { versions } = await known(db, eq(installedPlugins.robotId, robotId));
  return chooseDocument(latestPerSource(versions), robotId, source);
}

export async function findPlugin(db: Reader, robotId: string, source: string | null): Promise<Plugin | undefined> {
  return (await knownPlugin(db, robotId, source))?.plugin;
}
