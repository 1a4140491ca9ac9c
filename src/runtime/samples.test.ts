import { afterAll, describe, expect, it } from "vitest";
import { bareTrial, freshDatabase } from "../../tests/support/db";
import { sampleWriter } from "./samples";

describe("the sample writer", async () => {
  const { db, close } = await freshDatabase();
  afterAll(close);
  /** Each trial's samples as stored, in the exports' order, with the transaction that wrote each. */
  const stored = async (trialIds: string[]) =>
    db.$client<Array<{ trial_id: string; topic: string; rel_ms: number; data: unknown; xmin: string }>>`
      select trial_id, topic, rel_ms, data, xmin::text from trial_samples
      where trial_id in ${db.$client(trialIds)} order by trial_id, rel_ms, id`;

  it("writes a process's trials' samples in one commit, each as given and in the order it came", async () => {
    const writer = sampleWriter(db);
    // A study's size: fifty trials, ten joint states and a battery reading each (half a second of them).
    const trials = await Promise.all(Array.from({ length: 50 }, () => bareTrial(db)));
    const recorders = trials.map((id) => writer.recorder(id));
    const awkward = { text: 'quote " backslash \\ émoji 🤖 newline\n', list: [1.5, 0, 1e-7], nested: { a: null } };
    for (let k = 0; k < 10; k++)
      recorders.forEach((r) => r.add("/joint_states", 100 * k + 0.25, { position: [k, -0.5], k }));
    // Two at the same time: their order as they came.
    recorders.forEach((r) => r.add("/battery", 500, { first: true }));
    recorders.forEach((r) => r.add("/battery", 500, awkward));
    await recorders[0]!.close();
    const rows = await stored(trials);
    expect(rows).toHaveLength(50 * 12);
    expect(new Set(rows.map((r) => r.xmin)).size).toBe(1);
    for (const trialId of trials) {
      const own = rows.filter((r) => r.trial_id === trialId);
      expect(own.map((r) => [r.topic, r.rel_ms])).toEqual([
        ...[0, 1, 2, 3, 4].map((k) => ["/joint_states", 100 * k + 0.25]),
        ["/battery", 500],
        ["/battery", 500],
        ...[5, 6, 7, 8, 9].map((k) => ["/joint_states", 100 * k + 0.25]),
      ]);
      expect(own[5]!.data).toEqual({ first: true });
      expect(own[6]!.data).toEqual(awkward);
      expect(own[9]!.data).toEqual({ position: [7, -0.5], k: 7 });
    }
  });

  it("writes two minutes of fifty trials' joint states sent at once, in bounded statements, none lost or reordered", {
    timeout: 120_000,
  }, async () => {
    const writer = sampleWriter(db);
    const trials = await Promise.all(Array.from({ length: 50 }, () => bareTrial(db)));
    const recorders = trials.map((id) => writer.recorder(id));
    // 10 a second for 120 s, each trial's in turn as they come: 60,000 rows, past the writer's bound many times over.
    for (let k = 0; k < 1200; k++) recorders.forEach((r) => r.add("/joint_states", 100 * k, { k }));
    await recorders[0]!.close();
    const rows = await db.$client<Array<{ trial_id: string; k: number; xmin: string }>>`
      select trial_id, (data->>'k')::int as k, xmin::text from trial_samples
      where trial_id in ${db.$client(trials)} order by trial_id, id`;
    expect(rows).toHaveLength(60_000);
    for (const trialId of trials)
      expect(rows.filter((r) => r.trial_id === trialId).map((r) => r.k)).toEqual(
        Array.from({ length: 1200 }, (_, k) => k),
      );
    // Bounded: 2,000 rows a statement, so thirty commits, not one of 60,000 rows.
    expect(new Set(rows.map((r) => r.xmin)).size).toBe(30);
  });

  it("writes what waits half a second after the first sample came, without being asked", async () => {
    const writer = sampleWriter(db);
    const trialId = await bareTrial(db);
    writer.recorder(trialId).add("/joint_states", 1, { k: 1 });
    expect(await stored([trialId])).toEqual([]);
    await expect.poll(async () => (await stored([trialId])).length, { timeout: 5000 }).toBe(1);
  });

  it("loses no other trial's samples when one trial's are refused, and says whose were not stored", async () => {
    const refused: string[] = [];
    const writer = sampleWriter(db, (trialId, error) => refused.push(`${trialId}: ${String(error)}`));
    const [kept, deleted, alsoKept] = await Promise.all([bareTrial(db), bareTrial(db), bareTrial(db)]);
    for (const trialId of [kept, deleted, alsoKept]) writer.recorder(trialId).add("/battery", 1, { of: trialId });
    // Deleted while its samples waited: the statement of all three is refused, then each trial's is tried alone.
    await db.$client`delete from trials where id = ${deleted}`;
    await writer.recorder(kept!).close();
    expect((await stored([kept!, deleted!, alsoKept!])).map((r) => r.trial_id).sort()).toEqual([kept, alsoKept].sort());
    expect(refused).toHaveLength(1);
    expect(refused[0]).toMatch(new RegExp(`^${deleted}: `));
  });
});
