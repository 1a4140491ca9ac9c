// The plugin document a trial runs with. A published version's trials run
// with exactly the document it pinned when it was published, whatever is
// installed under that robotId now; a rehearsal (no version) and a version
// published before pinning use the current document of the source the
// experiment chose.
import { eq } from "drizzle-orm";
import type { Plugin } from "@/core/plugins";
import type { Database } from "@/store/client";
import { experimentVersions, experiments, pluginDocuments, trials } from "@/store/schema";
import { findPlugin } from "./catalog";

export type TrialPlugin =
  /** `plugin` is null when no plugin for `robotId` is installed: the trial runs with its robot unavailable. */
  | { ok: true; robotId: string; plugin: Plugin | null; pinnedHash: string | null }
  /** The trial must not open: the document its version pinned is gone. */
  | { ok: false; reason: string };

export async function trialPlugin(db: Pick<Database, "select">, trialId: string): Promise<TrialPlugin> {
  const [row] = await db
    .select({
      draftRobotId: experiments.robotId,
      draftSource: experiments.pluginSource,
      versionRobotId: experimentVersions.robotId,
      version: experimentVersions.version,
      pinnedHash: experimentVersions.pluginHash,
    })
    .from(trials)
    .innerJoin(experiments, eq(experiments.id, trials.experimentId))
    .leftJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
    .where(eq(trials.id, trialId));
  if (!row) return { ok: false, reason: "This trial does not exist." };
  // A published version names the robot it was published for; the draft may have moved on since.
  const robotId = row.versionRobotId ?? row.draftRobotId;
  if (!row.pinnedHash) {
    const plugin = (await findPlugin(db, robotId, row.draftSource)) ?? null;
    return { ok: true, robotId, plugin, pinnedHash: null };
  }
  const [document] = await db
    .select({ definition: pluginDocuments.definition })
    .from(pluginDocuments)
    .where(eq(pluginDocuments.hash, row.pinnedHash));
  if (!document) {
    return {
      ok: false,
      reason: `Version ${row.version} was published with a ${robotId} plugin document (${row.pinnedHash.slice(0, 12)}) that is no longer stored, so its trials cannot run. Publish the experiment again to run it with the plugin installed now.`,
    };
  }
  return { ok: true, robotId, plugin: document.definition as Plugin, pinnedHash: row.pinnedHash };
}
