// A link to the robot of a trial another runtime process runs, opened while a
// wizard who may run it is connected here, and used for one thing: an
// emergency stop goes straight to the robot from here, as well as to the
// owner, so it never waits on the database or on the owner. It is ready
// before the stop is asked for: a stop reads nothing.
import { eq } from "drizzle-orm";
import type { Plugin } from "@/core/plugins";
import type { Database } from "@/store/client";
import { logUnexpected } from "@/store/error-reference";
import { robots, trials } from "@/store/schema";
import type { RobotRecord } from "@/robots/registry";
import { trialPlugin } from "@/robots/trial-plugin";
import type { RobotLink } from "./robot";

interface Held {
  count: number;
  link: RobotLink | null;
  closed: boolean;
}

export function stopLinks(
  db: Database,
  /** A link to the robot, or null when it cannot be reached (its record says no way to). */
  linkFor: (plugin: Plugin, robot: RobotRecord) => RobotLink | null,
) {
  const held = new Map<string, Held>();
  /** Closed as the process stops: a page that follows a trial now (its host closing) opens no link to read for. */
  let shut = false;

  async function connect(trialId: string, entry: Held) {
    const chosen = await trialPlugin(db, trialId);
    const [row] = await db
      .select()
      .from(robots)
      .innerJoin(trials, eq(trials.assignedRobotId, robots.id))
      .where(eq(trials.id, trialId));
    // No plugin or no robot given yet: nothing here can stop (the owner still does).
    if (!chosen.ok || !chosen.plugin || !row) return;
    const link = linkFor(chosen.plugin, row.robots);
    if (!link) return;
    if (entry.closed) link.close();
    else entry.link = link;
  }

  return {
    /** Keeps the trial's stop link open until the function returned is called. */
    hold(trialId: string): () => void {
      if (shut) return () => {};
      let entry = held.get(trialId);
      if (!entry) {
        const fresh: Held = { count: 0, link: null, closed: false };
        held.set(trialId, fresh);
        // A read cut off by the process closing (its pool ended under it) is no fault: the link was not wanted any more.
        void connect(trialId, fresh).catch(
          (error: unknown) => fresh.closed || logUnexpected(error, "opening a robot link to stop"),
        );
        entry = fresh;
      }
      entry.count++;
      const own = entry;
      let released = false;
      return () => {
        if (released) return;
        released = true;
        if (--own.count > 0) return;
        own.closed = true;
        own.link?.close();
        if (held.get(trialId) === own) held.delete(trialId);
      };
    },
    /** Stops the trial's robot from here now; false when no link to it is connected here. */
    halt(trialId: string): boolean {
      const link = held.get(trialId)?.link;
      if (!link?.connected()) return false;
      link.halt();
      return true;
    },
    closeAll() {
      shut = true;
      for (const entry of held.values()) {
        entry.closed = true;
        entry.link?.close();
      }
      held.clear();
    },
  };
}

export type StopLinks = ReturnType<typeof stopLinks>;
