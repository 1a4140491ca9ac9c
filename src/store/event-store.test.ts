import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it } from "vitest";
import { bareTrial, bareWizard, freshDatabase } from "../../tests/support/db";
import { trials } from "./schema";
import {
  answeredRequests,
  appendEvents,
  appendMany,
  eventPages,
  eventsOfTrials,
  eventsSince,
  fencedOut,
  foldableEventsOfTrials,
  lastSeqOf,
  NOTIFY_CHANNEL,
  takeTrial,
  type TrialCursor,
  trialLog,
  trialLogJson,
  withPlace,
} from "./event-store";

/** Every piece a generator yields (this Node has no Array.fromAsync). */
async function piecesOf(pieces: AsyncGenerator<string>): Promise<string[]> {
  const all: string[] = [];
  for await (const piece of pieces) all.push(piece);
  return all;
}

describe("the trial event store", async () => {
  const { db, sql, close } = await freshDatabase();
  afterAll(close);

  const newTrial = () => bareTrial(db);

  /** What the trial's owner keeps in memory, read back from the database for the test. */
  async function cursor(trialId: string): Promise<TrialCursor> {
    const [trial] = await db.select().from(trials).where(eq(trials.id, trialId));
    return { id: trialId, lastSeq: (await eventsSince(db, trialId)).length, t0: trial!.t0 };
  }

  it("numbers events per trial, times them from t0, and moves the trial's status", async () => {
    const trialId = await newTrial();
    let clock = Date.parse("2026-01-01T10:00:00Z");
    const now = () => new Date(clock);
    await appendEvents(db, await cursor(trialId), [{ type: "note.added", text: "before" }], null, { now });
    clock += 1000;
    await appendEvents(
      db,
      await cursor(trialId),
      [{ type: "trial.started" }, { type: "step.entered", stepId: "s1", via: "start" }],
      null,
      { now },
    );
    clock += 2500;
    const [skipped] = await appendEvents(
      db,
      await cursor(trialId),
      [{ type: "action.skipped", stepId: "s1", actionId: "a1", deviation: "skipped" }],
      null,
      { now },
    );
    expect(skipped).toMatchObject({ seq: 4, relMs: 2500, deviation: "skipped", actionId: "a1" });
    const all = await eventsSince(db, trialId);
    expect(all.map((e) => [e.seq, e.type, e.relMs])).toEqual([
      [1, "note.added", null],
      [2, "trial.started", 0],
      [3, "step.entered", 0],
      [4, "action.skipped", 2500],
    ]);
    expect((await eventsSince(db, trialId, 2)).map((e) => e.seq)).toEqual([3, 4]);
    await appendEvents(db, await cursor(trialId), [{ type: "trial.completed" }], null, { now });
    const [trial] = await db.select().from(trials).where(eq(trials.id, trialId));
    expect(trial).toMatchObject({
      status: "completed",
      t0: new Date("2026-01-01T10:00:01Z"),
      endedAt: new Date("2026-01-01T10:00:03.500Z"),
    });
  });

  it("reads back each event as its append gave it: body, seq, time since t0, trial, server time and actor", async () => {
    const trialId = await newTrial();
    const wizard = await bareWizard(db);
    const now = () => new Date("2026-03-04T05:06:07.089Z");
    const appended = [
      ...(await appendEvents(db, await cursor(trialId), [{ type: "note.added", text: "ready" }], null, { now })),
      ...(await appendEvents(
        db,
        await cursor(trialId),
        [{ type: "trial.started" }, { type: "step.entered", stepId: "s1", via: "start" }],
        wizard,
        { now },
      )),
    ];
    const read = await eventsSince(db, trialId);
    expect(read).toEqual(appended);
    expect(read.map((e) => [e.serverTime.toISOString(), e.actorId, e.trialId])).toEqual([
      ["2026-03-04T05:06:07.089Z", null, trialId],
      ["2026-03-04T05:06:07.089Z", wizard, trialId],
      ["2026-03-04T05:06:07.089Z", wizard, trialId],
    ]);
  });

  it("stores every column as given, whatever the text holds, for 40 trials of 1 to 7 events in one append", async () => {
    const awkward = [
      'say "hi"',
      "back\\slash",
      "{braces}, commas",
      "null",
      "NULL",
      "",
      "naïve ☃ 日本",
      "two\nlines",
      "'",
    ];
    const ids = await Promise.all(Array.from({ length: 40 }, () => newTrial()));
    const appends = await Promise.all(
      ids.map(async (id, t) => ({
        cursor: await cursor(id),
        actorId: null,
        requestId: t % 2 ? `request-${t}` : null,
        events: [
          { type: "trial.started" as const },
          ...Array.from({ length: t % 7 }, (_, i) => ({
            type: "action.requested" as const,
            stepId: i % 3 ? "s1" : null,
            actionId: `${awkward[(t + i) % awkward.length]}-${i}`,
            actionType: "say",
            parameters: { text: awkward[(t + i) % awkward.length]!, volume: 0.5 },
            scripted: false,
            ...(i % 2 ? { deviation: "unscripted" as const } : {}),
          })),
        ],
      })),
    );
    const stored = await appendMany(db, appends);
    for (const [t, id] of ids.entries()) {
      expect(await eventsSince(db, id)).toEqual(stored[t]);
      expect(
        stored[t]!.map(({ seq, relMs, trialId, serverTime: _, actorId: __, ...event }) => [seq, relMs, trialId, event]),
      ).toEqual(appends[t]!.events.map((event, i) => [i + 1, 0, id, event]));
    }
    const columns = await sql<
      Array<{ step_id: string | null; action_id: string | null; deviation: boolean; request_id: string | null }>
    >`
      select step_id, action_id, deviation, request_id from trial_events where trial_id = ${ids[13]!} order by seq`;
    expect(columns).toEqual(
      appends[13]!.events.map((event) => ({
        step_id: "stepId" in event ? event.stepId : null,
        action_id: "actionId" in event ? event.actionId : null,
        deviation: "deviation" in event,
        request_id: "request-13",
      })),
    );
  });

  it("logs the robot's reports a command carries first, by no one and answering no request", async () => {
    const trialId = await newTrial();
    const wizard = await bareWizard(db);
    await appendEvents(db, await cursor(trialId), [{ type: "trial.started" }], null);
    const [stored] = await appendMany(db, [
      {
        cursor: await cursor(trialId),
        reports: [{ type: "note.added", text: "the robot's" }],
        events: [{ type: "note.added", text: "the wizard's" }],
        actorId: wizard,
        requestId: "request-1",
      },
    ]);
    expect(stored!.map((e) => [e.seq, e.actorId])).toEqual([
      [2, null],
      [3, wizard],
    ]);
    expect(await eventsSince(db, trialId, 1)).toEqual(stored);
    expect(await answeredRequests(db, trialId)).toEqual(new Map([["request-1", [3]]]));
  });

  it("reads the log as the fold reads it: each event's body, seq and time since t0, nothing each event repeats", async () => {
    const trialId = await newTrial();
    const now = () => new Date("2026-01-01T10:00:00Z");
    await appendEvents(db, await cursor(trialId), [{ type: "trial.started" }], null, { now });
    await appendEvents(
      db,
      await cursor(trialId),
      [{ type: "action.skipped", stepId: "s1", actionId: "a1", deviation: "skipped" }],
      null,
      { now },
    );
    expect(await trialLog(db, trialId)).toEqual([
      { type: "trial.started", seq: 1, relMs: 0 },
      { type: "action.skipped", stepId: "s1", actionId: "a1", deviation: "skipped", seq: 2, relMs: 0 },
    ]);
    expect(await trialLog(db, trialId, 1)).toEqual([expect.objectContaining({ seq: 2 })]);
    // The same events as the stored log, less the trial, server time and actor.
    expect(await trialLog(db, trialId)).toEqual(
      (await eventsSince(db, trialId)).map(({ trialId: _, serverTime: __, actorId: ___, ...event }) => event),
    );
  });

  it("gives the log as JSON text made from the stored payloads: the same events, at a long trial's size", async () => {
    const trialId = await newTrial();
    let clock = Date.parse("2026-01-01T10:00:00Z");
    const now = () => new Date(clock);
    // Before the start (no time since t0 yet), then two hours of a busy trial: 20,000 events in all.
    await appendEvents(db, await cursor(trialId), [{ type: "note.added", text: "set-up" }], null, { now });
    await appendEvents(db, await cursor(trialId), [{ type: "trial.started" }], null, { now });
    const awkward = ['"quoted" \\ back\\slash', "line\nbreak\ttab", "émoji 🤖 and 中文", "{}", "}", ""];
    for (let batch = 0; batch < 20; batch++) {
      clock += 360_000;
      const events = Array.from({ length: batch === 19 ? 998 : 1000 }, (_, i) => ({
        type: "action.requested" as const,
        stepId: "s1",
        actionId: `a${batch}-${i}`,
        actionType: "say",
        parameters: { text: awkward[i % awkward.length]!, nested: { list: [1, 2.5, null, true] } },
        scripted: i % 7 !== 0,
        ...(i % 7 === 0 ? { deviation: "unscripted" as const } : {}),
      }));
      await appendEvents(db, await cursor(trialId), events, null, { now });
    }
    // Written a page at a time: more than one piece, which together are the whole log.
    const pieces = await piecesOf(trialLogJson(db, trialId));
    expect(pieces.length).toBeGreaterThan(2);
    const text = pieces.join("");
    const expected = (await eventsSince(db, trialId)).map(
      ({ trialId: _, serverTime: __, actorId: ___, ...event }) => event,
    );
    expect(expected).toHaveLength(20_000);
    expect(JSON.parse(text)).toEqual(expected);
    expect(expected[0]).toMatchObject({ seq: 1, relMs: null });
    expect(await trialLog(db, trialId, 19_990)).toEqual(expected.slice(19_990));
    expect((await piecesOf(trialLogJson(db, trialId, 20_000))).join("")).toBe("[]");
  });

  it.each([
    ['{"type": "trial.started"}', 3, 0, '{"type": "trial.started","seq":3,"relMs":0}'],
    ['{"type": "note.added", "text": "}"}', 1, null, '{"type": "note.added", "text": "}","seq":1,"relMs":null}'],
    ["{}", 2, 5, '{"seq":2,"relMs":5}'],
  ])("places seq and time at the end of the payload %s", (payload, seq, relMs, json) => {
    expect(withPlace(payload, seq, relMs)).toBe(json);
    expect(JSON.parse(withPlace(payload, seq, relMs))).toEqual({ ...JSON.parse(payload), seq, relMs });
  });

  it("never lets two writers both write seq N: a stale cursor's append fails whole", async () => {
    const trialId = await newTrial();
    const stale = await cursor(trialId);
    await appendEvents(db, stale, [{ type: "note.added", text: "first" }], null);
    await expect(
      appendEvents(
        db,
        stale,
        [
          { type: "note.added", text: "second" },
          { type: "note.added", text: "third" },
        ],
        null,
      ),
    ).rejects.toThrow();
    expect((await eventsSince(db, trialId)).map((e) => [e.seq, e.type === "note.added" && e.text])).toEqual([
      [1, "first"],
    ]);
  });

  it("reads a log a page at a time, each after the last page's seq, up to a seq if asked", async () => {
    const trialId = await newTrial();
    await appendEvents(
      db,
      await cursor(trialId),
      [
        { type: "note.added", text: "1" },
        { type: "trial.started" },
        { type: "note.added", text: "3" },
        { type: "note.added", text: "4" },
        { type: "note.added", text: "5" },
      ],
      null,
    );
    const pages = async (page: Parameters<typeof eventPages>[2]) => {
      const seqs: number[][] = [];
      for await (const events of eventPages(db, trialId, page)) seqs.push(events.map((e) => e.seq));
      return seqs;
    };
    expect(await pages({ limit: 2 })).toEqual([[1, 2], [3, 4], [5]]);
    expect(await pages({ limit: 5 })).toEqual([[1, 2, 3, 4, 5]]);
    expect(await pages({ limit: 2, upTo: 3 })).toEqual([[1, 2], [3]]);
    expect(await lastSeqOf(db, trialId)).toBe(5);
    expect(await lastSeqOf(db, await newTrial())).toBe(0);
  });

  it("reads several trials' logs in one go, whole for exports and as the engine folds them", async () => {
    const [a, b, empty] = [await newTrial(), await newTrial(), await newTrial()];
    await appendEvents(db, await cursor(a), [{ type: "trial.started" }, { type: "note.added", text: "a" }], null);
    await appendEvents(db, await cursor(b), [{ type: "note.added", text: "b" }], null);
    const whole = await eventsOfTrials(db, [a, b, empty]);
    const foldable = await foldableEventsOfTrials(db, [a, b, empty]);
    expect([...foldable.keys()]).toEqual([a, b, empty]);
    for (const id of [a, b, empty])
      expect(foldable.get(id)).toEqual(
        whole.get(id)!.map(({ trialId: _t, serverTime: _s, actorId: _a, ...event }) => event),
      );
    expect(foldable.get(a)!.map((e) => [e.seq, e.type])).toEqual([
      [1, "trial.started"],
      [2, "note.added"],
    ]);
    expect(foldable.get(empty)).toEqual([]);
    expect(await foldableEventsOfTrials(db, [])).toEqual(new Map());
  });

  it("notifies listeners after the commit", async () => {
    const trialId = await newTrial();
    const heard: string[] = [];
    const listener = await sql.listen(NOTIFY_CHANNEL, (payload) => heard.push(payload));
    await appendEvents(
      db,
      await cursor(trialId),
      [
        { type: "note.added", text: "x" },
        { type: "note.added", text: "y" },
      ],
      null,
    );
    for (let i = 0; i < 50 && heard.length === 0; i++) await new Promise((r) => setTimeout(r, 20));
    await listener.unlisten();
    expect(heard).toContain(`${trialId}:2`);
  });

  it("refuses, whole, an append of an owner another process has taken the trial from since", async () => {
    const [kept, taken] = [await newTrial(), await newTrial()];
    const [oldEpoch, keptEpoch] = [await takeTrial(db, taken), await takeTrial(db, kept)];
    const newEpoch = await takeTrial(db, taken);
    expect(newEpoch).toBe(oldEpoch! + 1);
    const note = (text: string) => [{ type: "note.added" as const, text }];
    // Two trials in one statement, as the group writer sends them: the stale owner's fails both.
    const stale = appendMany(db, [
      { cursor: { ...(await cursor(kept)), epoch: keptEpoch! }, events: note("kept"), actorId: null },
      { cursor: { ...(await cursor(taken)), epoch: oldEpoch! }, events: note("late"), actorId: null },
    ]);
    await expect(stale.catch((e: unknown) => fencedOut(e))).resolves.toBe(true);
    expect([await lastSeqOf(db, kept), await lastSeqOf(db, taken)]).toEqual([0, 0]);
    await appendEvents(db, { ...(await cursor(taken)), epoch: newEpoch! }, note("new owner"), null);
    expect((await trialLog(db, taken)).map((e) => e.type === "note.added" && e.text)).toEqual(["new owner"]);
  });
});
