// Who holds a robot besides its live trial: a trial while it is open (from the
// moment its robot is chosen) or starts, a replay while it plays. A live trial's hold is its row (in progress or paused, and
// the unique index on the live trials' robots); these shorter holds are kept
// in this process and, for every other runtime process, as a PostgreSQL
// advisory lock on the robot, taken the way trials are owned (`trialLocks`, on
// a session of its own). A claim is taken before looking for a live trial on
// the robot, so a trial starting in one process and a replay in another never
// both find it free.
import type { RobotHolder } from "@/core/robots/registry";
import { logUnexpected } from "@/store/error-reference";
import { type NewSession, trialLocks } from "./trial-locks";

export type Claim = { ok: true; release: () => void } | { ok: false; holder: RobotHolder };

export interface RobotClaims {
  /** Holds the robot until `release`; `lost`: another process took it meanwhile (its session was lost). */
  take(robotId: string, holder: Exclude<RobotHolder, "elsewhere">, lost?: () => void): Promise<Claim>;
  close(): Promise<void>;
}

/** A robot's lock among the trials' (trial ids are bare uuids, so the two never meet). */
const PREFIX = "robot:";
const key = (robotId: string) => `${PREFIX}${robotId}`;

export function robotClaims(newSession: NewSession): RobotClaims {
  const held = new Map<string, { holder: RobotHolder; lost?: () => void }>();
  const locks = trialLocks(newSession, (locked) => {
    const robotId = locked.slice(PREFIX.length);
    const claim = held.get(robotId);
    held.delete(robotId);
    claim?.lost?.();
  });
  return {
    async take(robotId, holder, lost) {
      const here = held.get(robotId);
      if (here) return { ok: false, holder: here.holder };
      // Held from this moment: one session's advisory locks are its own to take again, so this map
      // is what keeps two holders of this process apart.
      const claim = { holder, lost };
      held.set(robotId, claim);
      let ok = false;
      try {
        ok = await locks.take(key(robotId));
      } finally {
        if (!ok) held.delete(robotId);
      }
      if (!ok) return { ok: false, holder: "elsewhere" };
      let released = false;
      return {
        ok: true,
        release() {
          if (released) return;
          released = true;
          if (held.get(robotId) === claim) held.delete(robotId);
          // A lock that could not be given back is held until its session ends: logged, not thrown at the replay.
          void locks.release(key(robotId)).catch((error: unknown) => logUnexpected(error, "releasing a robot"));
        },
      };
    },
    close: () => locks.close(),
  };
}
