// A process's trial locks against a real PostgreSQL: when the session that
// holds them is ended (as an administrator's pg_terminate_backend, or a
// database restart, ends it) and another process that was waiting for a
// trial's lock takes it at that moment, the first learns it as soon as its connection closes, before it
// would send the robot anything, and gives the trial up; a trial nobody took
// is taken again on the new session.
import { afterAll, describe, expect, it } from "vitest";
import { createSessionClient } from "../../src/store/client";
import { trialLocks } from "../../src/runtime/trial-locks";
import { freshDatabase } from "../support/db";

describe("trial locks", async () => {
  const { url, sql, close } = await freshDatabase();
  const lost: string[] = [];
  const mine = trialLocks(
    (closed) => createSessionClient(url, closed),
    (trialId) => lost.push(trialId),
  );
  /** Another process's lock session. */
  const rival = createSessionClient(url);
  afterAll(async () => {
    await Promise.all([mine.close(), rival.end()]);
    await close();
  });

  it("gives a trial up, before its next send, once its session ended and another process took it", async () => {
    expect([await mine.take("taken"), await mine.take("kept")]).toEqual([true, true]);
    expect(await mine.owns("taken")).toBe(true);
    const [session] = await sql<[{ pid: number }]>`select distinct pid from pg_locks where locktype = 'advisory'`;
    // The rival waits for the lock, so it has it the moment the session ends, before the first can take it again.
    const waiting = rival`select pg_advisory_lock(hashtextextended('taken', 0))`.execute();
    await expect
      .poll(async () => (await sql`select 1 from pg_locks where locktype = 'advisory' and not granted`).length)
      .toBe(1);
    await sql`select pg_terminate_backend(${session!.pid})`;
    await waiting;
    // Known as soon as the connection closed, well within the lease of a session last heard from.
    await expect.poll(() => mine.owns("taken")).toBe(false);
    expect(lost).toEqual(["taken"]);
    expect(await mine.owns("kept")).toBe(true);
    const [kept] = await rival<[{ ok: boolean }]>`select pg_try_advisory_lock(hashtextextended('kept', 0)) as ok`;
    expect(kept!.ok).toBe(false);
  });
});
