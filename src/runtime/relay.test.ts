// The event relay: another process's trials reach this one's clients through
// LISTEN/NOTIFY, and the relay listens only while a client here follows one
// (a runtime that runs its trials itself is not woken for every commit).
import { afterAll, describe, expect, it } from "vitest";
import { bareTrial, freshDatabase } from "../../tests/support/db";
import type { StoredEvent } from "@/core/trial";
import { appendEvents } from "@/store/event-store";
import { eventRelay } from "./relay";

describe("the event relay", async () => {
  const { db, sql, close } = await freshDatabase();
  afterAll(close);
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
  /** What the database's sessions last ran about the channel: "listen" or "unlisten" for the relay's session. */
  const listenState = async () => {
    const rows = await sql<Array<{ query: string }>>`
      select query from pg_stat_activity where datname = current_database() and (query ilike 'listen "hri_trial_events"%' or query ilike 'unlisten "hri_trial_events"%')`;
    return rows.map((r) => r.query.trim().split(" ")[0]!.toLowerCase());
  };
  const until = async (done: () => boolean | Promise<boolean>) => {
    for (let i = 0; i < 250 && !(await done()); i++) await new Promise((r) => setTimeout(r, 20));
  };
  const unlistened = async () => (await listenState()).join() === "unlisten";
  const seqs = (batches: StoredEvent[][]) => batches.flat().map((e) => e.seq);

  it("listens only while a client follows a trial, and hears what committed before it listened", async () => {
    const relay = await eventRelay(db, sql);
    const trialId = await bareTrial(db);
    expect(relay.listening).toBe(false);
    // Committed after the client's read (seq 0) and before it follows: caught up once the relay listens.
    await write(trialId, 0, 3);
    const heard: StoredEvent[][] = [];
    const stop = relay.follow(trialId, 0, (events) => heard.push(events));
    expect(relay.listening).toBe(true);
    await until(() => seqs(heard).length === 3);
    await write(trialId, 3, 2);
    await until(() => seqs(heard).length === 5);
    expect(seqs(heard)).toEqual([1, 2, 3, 4, 5]);
    expect(await listenState()).toContain("listen");
    stop();
    expect(relay.listening).toBe(false);
    await until(unlistened);
    expect(await listenState()).toEqual(["unlisten"]);
    // Not following, so not told: a later commit reaches no one here.
    await write(trialId, 5, 1);
    expect(seqs(heard)).toEqual([1, 2, 3, 4, 5]);
    await relay.close();
  });

  it("stops listening when the last of many followers leaves, each follower having had its own trial's events once, in order", async () => {
    const relay = await eventRelay(db, sql);
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
    // All but one leave: still listening for the last.
    for (const stop of stops.slice(1)) stop();
    expect(relay.listening).toBe(true);
    stops[0]!();
    expect(relay.listening).toBe(false);
    await until(unlistened);
    expect(await listenState()).toEqual(["unlisten"]);
    await relay.close();
  });

  it("hears a trial followed again right after the last follower left (the unlisten still under way)", async () => {
    const relay = await eventRelay(db, sql);
    const trialId = await bareTrial(db);
    relay.follow(trialId, 0, () => {})();
    const heard: StoredEvent[][] = [];
    relay.follow(trialId, 0, (events) => heard.push(events));
    await write(trialId, 0, 5);
    await until(() => seqs(heard).length === 5);
    expect(seqs(heard)).toEqual([1, 2, 3, 4, 5]);
    expect(relay.listening).toBe(true);
    await relay.close();
    expect(relay.listening).toBe(false);
  });
});
