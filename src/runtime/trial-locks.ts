// Which trials this runtime process owns: PostgreSQL advisory locks, held on
// one connection of their own. Such locks live as long as that connection,
// so when it dies (the database restarted, a network blip, an administrator
// ended it) a new one is taken and every lock held is taken again on it; a
// trial whose lock another process took meanwhile is given up, so two
// processes never run one trial.
import type postgres from "postgres";

export interface TrialLocks {
  /** Whether this process now owns the trial (locks count: each take needs a release). */
  take(trialId: string): Promise<boolean>;
  release(trialId: string): Promise<void>;
  close(): Promise<void>;
}

export function trialLocks(
  sql: postgres.Sql,
  /** Told of each trial lost while the connection was replaced: its host must stop. */
  lost: (trialId: string) => void,
): TrialLocks {
  let connection: Promise<postgres.ReservedSql> = sql.reserve();
  const held = new Map<string, number>();

  const lock = async (c: postgres.ReservedSql, trialId: string) =>
    Boolean((await c`select pg_try_advisory_lock(hashtextextended(${trialId}, 0)) as ok`)[0]?.ok);

  /** A new connection, with every lock held before taken again on it. */
  async function reconnect(broken: postgres.ReservedSql) {
    if ((await connection) !== broken) return connection;
    connection = (async () => {
      try {
        broken.release();
      } catch {
        // Already gone with its socket.
      }
      const fresh = await sql.reserve();
      for (const [trialId, count] of [...held]) {
        let ok = true;
        for (let i = 0; i < count && ok; i++) ok = await lock(fresh, trialId);
        if (!ok) {
          held.delete(trialId);
          lost(trialId);
        }
      }
      return fresh;
    })();
    return connection;
  }

  /** Runs on the lock connection; once more on a new one if it had died. */
  async function onConnection<T>(work: (c: postgres.ReservedSql) => Promise<T>): Promise<T> {
    const c = await connection;
    try {
      return await work(c);
    } catch (error) {
      if (!isConnectionLost(error)) throw error;
      return work(await reconnect(c));
    }
  }

  return {
    async take(trialId) {
      const ok = await onConnection((c) => lock(c, trialId));
      if (ok) held.set(trialId, (held.get(trialId) ?? 0) + 1);
      return ok;
    },
    async release(trialId) {
      const count = held.get(trialId) ?? 0;
      if (count === 0) return;
      if (count === 1) held.delete(trialId);
      else held.set(trialId, count - 1);
      await onConnection((c) => c`select pg_advisory_unlock(hashtextextended(${trialId}, 0))`);
    },
    async close() {
      held.clear();
      (await connection).release();
    },
  };
}

/** Errors that mean the connection itself is gone, not that the query was wrong. */
function isConnectionLost(error: unknown): boolean {
  const e = error as { code?: string; message?: string };
  return (
    e?.code === "CONNECTION_CLOSED" ||
    e?.code === "CONNECTION_ENDED" ||
    e?.code === "CONNECTION_DESTROYED" ||
    e?.code === "57P01" || // terminated by an administrator
    e?.code === "ECONNRESET" ||
    /socket|connection/i.test(e?.message ?? "")
  );
}
