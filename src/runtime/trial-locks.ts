// Which trials this runtime process owns: PostgreSQL advisory locks, held on
// a connection of their own (`createSessionClient`). Such locks live as long
// as that connection's session, so every lock operation also reads the
// session's id: when it has changed (the database restarted, a network blip,
// an administrator ended the connection), every lock held is taken again on
// the new session, and a trial whose lock another process took meanwhile is
// given up, so two processes never run one trial. A lock query on a
// connection that died under it can fail, or never answer at all: either way
// the client is dropped and the query runs once more on a new one. While
// locks are held, the session is asked for its id every second too, so a
// lock lost while nothing else happens is found (and its trial given up, its
// clients told) within about a second, not at the next trial opened.
import type postgres from "postgres";
import { answered as within, connectionLost } from "@/store/client";

export interface TrialLocks {
  /** Whether this process now owns the trial (locks count: each take needs a release). */
  take(trialId: string): Promise<boolean>;
  release(trialId: string): Promise<void>;
  /**
   * Whether this process still holds the trial's lock, its session heard
   * from within the last LEASE_MS (else asked now, and a session found
   * changed mended first): what a robot send waits on, so a process that was
   * frozen or cut off sends nothing before it knows it still owns the trial.
   */
  owns(trialId: string): Promise<boolean>;
  close(): Promise<void>;
}

/** A new session client (see `createSessionClient`), each time the one before is dropped; `closed`: its connection closed. */
export type NewSession = (closed: () => void) => postgres.Sql;

export function trialLocks(
  newSession: NewSession,
  /** Told of each trial lost with a session: its host must stop. */
  lost: (trialId: string) => void,
): TrialLocks {
  let shut = false;
  // A session whose connection closed: its locks are looked at again at once (once the client has let the
  // connection go), not at the watch's next round.
  const open = () =>
    newSession(() => {
      if (held.size && !shut) setTimeout(() => void check().catch(() => {}), 0);
    });
  let session = open();
  const held = new Map<string, number>();
  let sessionId: number | null = null;
  // One operation at a time, so a session change is noticed and mended before the next.
  let queue: Promise<unknown> = Promise.resolve();
  let watching = false;
  /** When the session last answered as the one holding every lock in `held`. */
  let heardAt = 0;

  const tryLock = async (trialId: string) => {
    const [row] = await session<[{ ok: boolean; pid: number }]>`
      select pg_try_advisory_lock(hashtextextended(${trialId}, 0)) as ok, pg_backend_pid() as pid`;
    return row;
  };

  /** On a new session: every lock held before, taken again; those another process holds now, given up. */
  async function mend(pid: number) {
    if (sessionId === null || sessionId === pid) {
      sessionId = pid;
      heardAt = Date.now();
      return;
    }
    sessionId = pid;
    for (const [trialId, count] of [...held]) {
      let ok = true;
      for (let i = 0; i < count && ok; i++) ok = (await tryLock(trialId)).ok;
      if (!ok) {
        held.delete(trialId);
        lost(trialId);
      }
    }
    heardAt = Date.now();
  }

  /** Once more on a new client if the connection dropped under the query, or it did not answer. */
  const retried = async <T>(work: () => Promise<T>): Promise<T> => {
    try {
      return await answered(work());
    } catch (error) {
      if (!connectionLost(error)) throw error;
      void session.end({ timeout: 0 }).catch(() => {});
      session = open();
      return answered(work());
    }
  };

  const serial = <T>(work: () => Promise<T>): Promise<T> => {
    const run = queue.then(work);
    queue = run.catch(() => undefined);
    return run;
  };

  /** Asks the session for its id, and mends it if it changed. */
  const check = () =>
    serial(async () => {
      const [row] = await retried(() => session<[{ pid: number }]>`select pg_backend_pid() as pid`);
      await mend(row.pid);
    });

  const watch = setInterval(() => {
    if (!held.size || watching) return;
    watching = true;
    void check()
      // The database away: asked again next time; the hosts' appends fail meanwhile on their own.
      .catch(() => {})
      .finally(() => {
        watching = false;
      });
  }, WATCH_MS);
  watch.unref?.();

  return {
    take: (trialId) =>
      serial(async () => {
        const { ok, pid } = await retried(() => tryLock(trialId));
        await mend(pid);
        if (ok) held.set(trialId, (held.get(trialId) ?? 0) + 1);
        return ok;
      }),
    release: (trialId) =>
      serial(async () => {
        const count = held.get(trialId) ?? 0;
        if (count === 0) return;
        if (count === 1) held.delete(trialId);
        else held.set(trialId, count - 1);
        const [row] = await retried(
          () => session<[{ pid: number }]>`
            select pg_advisory_unlock(hashtextextended(${trialId}, 0)), pg_backend_pid() as pid`,
        );
        await mend(row.pid);
      }),
    async owns(trialId) {
      if (held.has(trialId) && Date.now() - heardAt < LEASE_MS) return true;
      await check().catch(() => {});
      return held.has(trialId) && Date.now() - heardAt < LEASE_MS;
    },
    async close() {
      shut = true;
      clearInterval(watch);
      held.clear();
      await session.end({ timeout: 5 });
    },
  };
}

/** How often a session holding locks is asked whether it is still the one that took them. */
const WATCH_MS = 1000;
/** How long the session's last answer vouches for the locks: a few of the watch's rounds. */
const LEASE_MS = 3000;

const answered = <T>(query: Promise<T>) => within(query, "The lock connection did not answer.");
