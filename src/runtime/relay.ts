// Events of trials another runtime process owns reach this process's clients
// through PostgreSQL LISTEN/NOTIFY: the owner notifies at commit, we read
// what is new from the log. No other broker.
import type postgres from "postgres";
import type { Database } from "@/store/client";
import type { StoredEvent } from "@/core/trial";
import { eventsSince, NOTIFY_CHANNEL } from "@/store/event-store";

interface Follower {
  lastSeq: number;
  push(events: StoredEvent[]): void;
}

export async function eventRelay(db: Database, sql: postgres.Sql) {
  const followers = new Map<string, Set<Follower>>();
  const catchUp = async (trialId: string) => {
    const group = followers.get(trialId);
    if (!group?.size) return;
    const from = Math.min(...[...group].map((f) => f.lastSeq));
    const events = await eventsSince(db, trialId, from);
    for (const f of group) {
      const fresh = events.filter((e) => e.seq > f.lastSeq);
      if (!fresh.length) continue;
      f.lastSeq = fresh.at(-1)!.seq;
      f.push(fresh);
    }
  };
  /**
   * A read that fails (the database restarting) is read again from the same place at the trial's next notice or
   * the listener's reconnection: nothing is lost, and the failure never takes the process down (an unhandled
   * rejection ends a Bun process: found by tests/runtime/fencing.test.ts, whose runtime died as PostgreSQL shut down).
   */
  const catchUpSoon = (trialId: string) =>
    void catchUp(trialId).catch((error: unknown) =>
      console.warn(`[runtime] trial ${trialId}: its new events are read at the next notice: ${String(error)}`),
    );
  const listener = await sql.listen(
    NOTIFY_CHANNEL,
    (payload) => catchUpSoon(payload.split(":")[0]!),
    // Listening again after the listening connection was lost: what committed meanwhile notified no one here.
    () => {
      for (const trialId of followers.keys()) catchUpSoon(trialId);
    },
  );
  return {
    /** Follows a trial from `lastSeq`; returns a function that stops following. */
    follow(trialId: string, lastSeq: number, push: (events: StoredEvent[]) => void) {
      const follower: Follower = { lastSeq, push };
      const group = followers.get(trialId) ?? new Set();
      followers.set(trialId, group.add(follower));
      // Anything committed between the caller's read and this subscription.
      catchUpSoon(trialId);
      return () => {
        group.delete(follower);
        if (!group.size && followers.get(trialId) === group) followers.delete(trialId);
      };
    },
    close: () => listener.unlisten(),
  };
}

export type EventRelay = Awaited<ReturnType<typeof eventRelay>>;
