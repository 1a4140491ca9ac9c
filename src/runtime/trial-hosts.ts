// The live trials this runtime process owns. A trial is owned by one process
// at a time: the first to take its PostgreSQL advisory lock.
import { eq } from "drizzle-orm";
import type postgres from "postgres";
import type { Plugin } from "@/core/plugins";
import type { Database } from "@/store/client";
import { experimentVersions, trials } from "@/store/schema";
import { trialPlugin } from "@/robots/trial-plugin";
import type { RobotLink } from "./robot";
import { TrialHost } from "./trial-host";

export interface TrialHosts {
  /** The trial's host in this process, or null while another process owns the trial. */
  get(trialId: string): Promise<TrialHost | null>;
  closeAll(): Promise<void>;
}

export function trialHosts(
  db: Database,
  lockConnection: postgres.ReservedSql,
  /** The robot for a trial's plugin document; `plugin` is null when none is installed for `robotId`. */
  robotFor: (plugin: Plugin | null, robotId: string) => RobotLink | Promise<RobotLink>,
  onRobotStatus: (trialId: string, connected: boolean, detail?: string) => void,
): TrialHosts {
  const hosts = new Map<string, Promise<TrialHost | null>>();

  async function open(trialId: string) {
    const [owned] = await lockConnection`select pg_try_advisory_lock(hashtextextended(${trialId}, 0)) as ok`;
    if (!owned?.ok) return null;
    const [row] = await db
      .select({ snapshot: experimentVersions.snapshot, rehearsal: trials.rehearsalSnapshot })
      .from(trials)
      .leftJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
      .where(eq(trials.id, trialId));
    const protocol = row?.snapshot ?? row?.rehearsal;
    if (!protocol) throw new Error("This trial has no protocol to run.");
    const chosen = await trialPlugin(db, trialId);
    if (!chosen.ok) {
      // Refused, not owned: another attempt (or process) may take it once the cause is fixed.
      await lockConnection`select pg_advisory_unlock(hashtextextended(${trialId}, 0))`;
      throw new Error(chosen.reason);
    }
    const host = await TrialHost.open(db, trialId, protocol, await robotFor(chosen.plugin, chosen.robotId));
    host.onRobotStatus((connected, detail) => onRobotStatus(trialId, connected, detail));
    return host;
  }

  return {
    get(trialId) {
      let host = hosts.get(trialId);
      if (!host) {
        host = open(trialId);
        hosts.set(trialId, host);
        // Not owned here (yet): ask again next time, the owner may have gone.
        host.then(
          (h) => h ?? hosts.delete(trialId),
          () => hosts.delete(trialId),
        );
      }
      return host;
    },
    async closeAll() {
      for (const host of hosts.values()) await (await host.catch(() => null))?.close();
      hosts.clear();
    },
  };
}
