import { afterAll, describe, expect, it } from "vitest";
import { bareTrial, freshDatabase } from "../../tests/support/db";
import { eventsSince } from "@/store/event-store";
import { groupWriter } from "./log-writer";

describe("the group writer", async () => {
  const { db, close } = await freshDatabase();
  afterAll(close);
  const note = (text: string) => [{ type: "note.added" as const, text }];
  const at = (id: string, lastSeq = 0) => ({ id, lastSeq, t0: null });
  /** The transaction that wrote each trial's events: rows of one commit share it. */
  const writtenBy = async (trialIds: string[]) =>
    (
      await db.$client<Array<{ trial_id: string; xmin: string }>>`
      select trial_id, xmin::text from trial_events where trial_id in ${db.$client(trialIds)}`
    ).map((r) => r.xmin);

  it("writes what arrives during a commit in the next one, and answers each trial with its own events", async () => {
    const writer = groupWriter(db);
    const trials = await Promise.all(Array.from({ length: 6 }, () => bareTrial(db)));
    // The first starts a commit; the five that come while it is under way go in one more.
    const first = writer.append({ cursor: at(trials[0]!), events: note("first"), actorId: null });
    const rest = trials
      .slice(1)
      .map((id, i) => writer.append({ cursor: at(id), events: [...note(`a${i}`), ...note(`b${i}`)], actorId: null }));
    expect(await first).toMatchObject([{ seq: 1, trialId: trials[0], text: "first" }]);
    const answered = await Promise.all(rest);
    answered.forEach((events, i) =>
      expect(events).toMatchObject([
        { seq: 1, trialId: trials[i + 1], text: `a${i}` },
        { seq: 2, trialId: trials[i + 1], text: `b${i}` },
      ]),
    );
    expect(new Set(await writtenBy(trials.slice(1))).size).toBe(1);
    expect(new Set(await writtenBy(trials)).size).toBe(2);
  });

  it("makes an append given as a function up as its commit begins, and fails only the one that cannot be made up", async () => {
    const writer = groupWriter(db);
    const [busy, late, broken] = await Promise.all([bareTrial(db), bareTrial(db), bareTrial(db)]);
    const words = ["asked"];
    const opening = writer.append({ cursor: at(busy!), events: note("opening"), actorId: null });
    // Waits behind the commit under way: what its trial learns meanwhile is in it.
    const later = writer.append(() => ({ cursor: at(late!), events: words.map((w) => note(w)[0]!), actorId: null }));
    const failing = writer
      .append(() => {
        throw new Error("no events to make");
      })
      .then(
        () => "made",
        (error: Error) => error.message,
      );
    words.push("learnt meanwhile");
    await opening;
    expect(await later).toMatchObject([
      { seq: 1, text: "asked" },
      { seq: 2, text: "learnt meanwhile" },
    ]);
    expect(await failing).toBe("no events to make");
    expect(await eventsSince(db, broken!)).toEqual([]);
    // The writer carries on.
    expect(await writer.append({ cursor: at(broken!), events: note("after"), actorId: null })).toMatchObject([
      { seq: 1, text: "after" },
    ]);
  });

  it("fails only the trial whose cursor is stale: the others in its commit are stored", async () => {
    const writer = groupWriter(db);
    const [busy, stale, fine] = await Promise.all([bareTrial(db), bareTrial(db), bareTrial(db)]);
    await writer.append({ cursor: at(stale!), events: note("already there"), actorId: null });
    const opening = writer.append({ cursor: at(busy!), events: note("opening"), actorId: null });
    const outcomes = await Promise.allSettled([
      writer.append({ cursor: at(stale!), events: note("written twice?"), actorId: null }),
      writer.append({ cursor: at(fine!), events: note("fine"), actorId: null }),
    ]);
    await opening;
    expect(outcomes[0].status).toBe("rejected");
    expect(outcomes[1]).toMatchObject({ status: "fulfilled", value: [{ seq: 1, text: "fine" }] });
    expect((await eventsSince(db, stale!)).map((e) => (e as { text?: string }).text)).toEqual(["already there"]);
    expect(await eventsSince(db, fine!)).toHaveLength(1);
  });
});
