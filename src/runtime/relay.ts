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
  const listener = await sql.listen(
    NOTIFY_CHANNEL,
    (payload) => void catchUp(payload.split(":")[0]!),
    // Listening again after the listening connection was lost: what committed meanwhile notified no one here.
    () => {
      for (const trialId of followers.keys()) void catchUp(trialId);
    },
  );
  return {
    /** Follows a trial from `lastSeq`; returns a function that stops following. */
    follow(trialId: string, lastSeq: number, push: (events: StoredEvent[]) => void) {
      const follower: Follower = { lastSeq, push };
      const group = followers.get(trialId) ?? new Set();
      followers.set(trialId, group.add(follower));
      // Anything committed between the caller's read and this subscription.
      void catchUp(trialId);
      return () => {
        group.delete(follower);
        if (!group.size && followers.get(trialId) === group) followers.delete(trialId);
      };
    },
    close: () => listener.unlisten(),
  };
}

export type EventRelay = Awaited<ReturnType<typeof eventRelay>>;
