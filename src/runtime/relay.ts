// Events of trials another runtime process owns reach this process's clients
// through PostgreSQL LISTEN/NOTIFY: the owner notifies at commit, we read
// what is new from the log. No other broker. The relay listens only while a
// client here follows such a trial: a listening connection is woken for every
// commit of every trial (a signal, a wake-up and a message each), and a
// runtime that runs all its trials itself would pay that twice a line for
// notices it drops.
import type postgres from "postgres";
import type { Database } from "@/store/client";
import type { StoredEvent } from "@/core/trial";
import { eventsSince, NOTIFY_CHANNEL } from "@/store/event-store";

interface Follower {
  lastSeq: number;
  push(events: StoredEvent[]): void;
}

/** How soon a LISTEN the database refused is tried again. */
const RETRY_LISTEN_MS = 1000;

type Listening = Promise<{ unlisten: () => Promise<void> }>;

export async function eventRelay(db: Database, sql: postgres.Sql) {
  const followers = new Map<string, Set<Follower>>();
  let listening: Listening | null = null;
  let closed = false;
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
   * Listening from now on. Each time the LISTEN takes effect (the first time, and again after the listening
   * connection was lost and came back), every followed trial is read: what committed before it took effect
   * sent its notice to no one.
   */
  const listen = (): Listening => {
    const started = sql.listen(
      NOTIFY_CHANNEL,
      (payload) => void catchUp(payload.split(":")[0]!),
      () => {
        for (const trialId of followers.keys()) void catchUp(trialId);
      },
    );
    // Refused (the database unreachable as a client came): tried again while anyone here still follows.
    started.catch(() => {
      if (listening !== started) return;
      listening = null;
      setTimeout(() => {
        if (!listening && !closed && followers.size > 0) listening = listen();
      }, RETRY_LISTEN_MS);
    });
    return started;
  };
  const unfollow = (trialId: string, follower: Follower) => {
    const group = followers.get(trialId);
    if (!group?.delete(follower) || group.size > 0) return;
    followers.delete(trialId);
    if (followers.size > 0 || !listening) return;
    const stopping = listening;
    listening = null;
    void stopping.then((l) => l.unlisten()).catch(() => {});
  };
  return {
    /** Follows a trial from `lastSeq`; returns a function that stops following. */
    follow(trialId: string, lastSeq: number, push: (events: StoredEvent[]) => void) {
      const follower: Follower = { lastSeq, push };
      const group = followers.get(trialId) ?? new Set();
      followers.set(trialId, group.add(follower));
      // Anything committed between the caller's read and this subscription: read once listening (as the
      // listen takes effect, above), or now when already listening.
      if (listening) void catchUp(trialId);
      else if (!closed) listening = listen();
      return () => unfollow(trialId, follower);
    },
    /** Whether the relay listens now: only while it follows a trial. */
    get listening() {
      return listening !== null;
    },
    close: async () => {
      closed = true;
      const stopping = listening;
      listening = null;
      await stopping?.then((l) => l.unlisten());
    },
  };
}

export type EventRelay = Awaited<ReturnType<typeof eventRelay>>;
