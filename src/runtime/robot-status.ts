// A trial's robot status on pages of every runtime process: the owner says
// each change through PostgreSQL (NOTIFY), as it says its events; a process
// that does not run the trial tells the pages it serves for it. A page that
// arrives there is first told the status the owner last wrote on the robot's
// record (src/runtime/robot-health.ts).
import { eq } from "drizzle-orm";
import type postgres from "postgres";
import { oneAfterAnother } from "@/core/one-after-another";
import type { Database } from "@/store/client";
import { logUnexpected } from "@/store/error-reference";
import { robots, trials } from "@/store/schema";

const CHANNEL = "hri_trial_robot";

export interface RobotStatus {
  connected: boolean;
  detail?: string;
}

export async function robotStatusRelay(
  sql: postgres.Sql,
  /** A status another process announced, for the pages of this one (told only where it does not run the trial). */
  heard: (trialId: string, status: RobotStatus) => void,
) {
  const listener = await sql.listen(CHANNEL, (payload) => {
    try {
      const { trialId, connected, detail } = JSON.parse(payload) as RobotStatus & { trialId: string };
      heard(trialId, { connected, ...(detail ? { detail } : {}) });
    } catch (error) {
      logUnexpected(error, "a robot status announced by another runtime");
    }
  });
  // Closed as the process stops: a link's close heard after it (its socket closing late) is told to nobody,
  // the database going too. What was said before it still goes out: the links the stop closes say so to the
  // pages of the other processes, before the pool ends under them.
  let closed = false;
  // One after another: notices sent at once would go out on several of the pool's connections and commit in
  // any order, and a page elsewhere could be left on "dropped" after the robot came back.
  const inTurn = oneAfterAnother();
  return {
    announce(trialId: string, status: RobotStatus) {
      if (closed) return;
      void inTurn(() => sql.notify(CHANNEL, JSON.stringify({ trialId, ...status }))).catch((error: unknown) =>
        logUnexpected(error, "announcing a robot status"),
      );
    },
    close: async () => {
      closed = true;
      await inTurn(async () => {});
      await listener.unlisten();
    },
  };
}

/** The trial's robot as its record last said: its name, and whether the owner found it connected. */
export async function recordedRobot(db: Database, trialId: string) {
  const [row] = await db
    .select({ name: robots.name, connected: robots.connected })
    .from(trials)
    .innerJoin(robots, eq(robots.id, trials.assignedRobotId))
    .where(eq(trials.id, trialId));
  return row ?? null;
}
