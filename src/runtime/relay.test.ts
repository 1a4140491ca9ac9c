// The event relay: another process's trials reach this one's clients through
// LISTEN/NOTIFY and a read of the log, each follower's events once and in
// order, and nothing lost while the listening connection was down.
import { afterAll, describe, expect, it } from "vitest";
import { bareTrial, freshDatabase } from "../../tests/support/db";
import type { StoredEvent } from "@/core/trial";
import { appendEvents } from "@/store/event-store";
import { eventRelay } from "./relay";

describe("the event relay", async () => {
  const { db, sql, close } = await freshDatabase();
  /** Another process's writes: `count` notes after `lastSeq`, one commit each. */
  const write = async (trialId: string, lastSeq: number, count: number) => {
    for (let i = 0; i < count; i++)
      await appendEvents(
        db,
        { id: trialId, lastSeq: lastSeq + i, t0: null },
        [{ type: "note.added", text: `n${lastSeq + i + 1}` }],
        null,
      );
  };
  const until = async (done: () => boolean) => {
    for (let i = 0; i < 250 && !done(); i++) await new Promise((r) => setTimeout(r, 20));
  };
  const seqs = (batches: StoredEvent[][]) => batches.flat().map((e) => e.seq);
  const relay = await eventRelay(db, sql);
  afterAll(async () => {
    await relay.close();
    await close();
  });

  it("gives a follower what committed before it followed, then each commit, and nothing once it stops", async () => {
    const trialId = await bareTrial(db);
    // Committed after the client's read (seq 0) and before it follows.
    await write(trialId, 0, 3);
    const heard: StoredEvent[][] = [];
    const stop = relay.follow(trialId, 0, (events) => heard.push(events));
    await until(() => seqs(heard).length === 3);
    await write(trialId, 3, 2);
    await until(() => seqs(heard).length === 5);
    expect(seqs(heard)).toEqual([1, 2, 3, 4, 5]);
    stop();
    await write(trialId, 5, 1);
    await new Promise((r) => setTimeout(r, 200));
    expect(seqs(heard)).toEqual([1, 2, 3, 4, 5]);
  });

  it("gives each of 200 followers of 20 trials its own trial's events, once each, in order", async () => {
    const trialIds = await Promise.all(Array.from({ length: 20 }, () => bareTrial(db)));
    const heard = trialIds.map(() => Array.from({ length: 10 }, () => [] as StoredEvent[][]));
    const stops = trialIds.flatMap((trialId, t) =>
      heard[t]!.map((mine) => relay.follow(trialId, 0, (events) => mine.push(events))),
    );
    await Promise.all(trialIds.map((trialId) => write(trialId, 0, 50)));
    await until(() => heard.every((followers) => followers.every((mine) => seqs(mine).length === 50)));
    for (const [t, followers] of heard.entries())
      for (const mine of followers) {
        expect(seqs(mine)).toEqual(Array.from({ length: 50 }, (_, i) => i + 1));
        expect(new Set(mine.flat().map((e) => e.trialId))).toEqual(new Set([trialIds[t]]));
      }
    for (const stop of stops) stop();
  });

  it("catches a follower up on what committed while its listening connection was down, with no commit after", async () => {
    const trialId = await bareTrial(db);
    const heard: StoredEvent[][] = [];
    relay.follow(trialId, 0, (events) => heard.push(events));
    await write(trialId, 0, 1);
    await until(() => seqs(heard).length === 1);
    // The listening session ended (a restart, a network loss, an administrator): its client listens again.
    await sql`select pg_terminate_backend(pid) from pg_stat_activity
      where datname = current_database() and query ilike 'listen "hri_trial_events"%'`;
    await write(trialId, 1, 3);
    await until(() => seqs(heard).length === 4);
    expect(seqs(heard)).toEqual([1, 2, 3, 4]);
  });

  it("reads again at the next notice after a read of the log failed, and the failure ends nothing", async () => {
    // The log's reads fail while `failing` (as PostgreSQL shutting down answers); the rest is the database as it is.
    // Failing from the start and counted: the follower's first read and the two notices' reads are all refused
    // before the reads succeed again, however slowly the machine runs them (a first read let through once ran
    // after both writes had committed, under CI's load, and gave them).
    let failing = true;
    let refused = 0;
    const real = db.$client;
    const flaky = Object.assign(Object.create(db) as typeof db, {
      $client: ((...args: Parameters<typeof real>) => {
        if (!failing) return real(...args);
        refused++;
        return Promise.reject(Object.assign(new Error("shutting down"), { code: "57P03" }));
      }) as typeof real,
    });
    const own = await eventRelay(flaky, sql);
    const trialId = await bareTrial(db);
    const heard: StoredEvent[][] = [];
    own.follow(trialId, 0, (events) => heard.push(events));
    await write(trialId, 0, 2);
    await until(() => refused === 3);
    failing = false;
    expect(refused).toBe(3);
    expect(seqs(heard)).toEqual([]);
    await write(trialId, 2, 1);
    await until(() => seqs(heard).length === 3);
    expect(seqs(heard)).toEqual([1, 2, 3]);
    await own.close();
  });
});
