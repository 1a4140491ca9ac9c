// Robot data for the analysis chart: an hour at 50 Hz is far more than a
// chart can draw, so the server thins it by equal slices of time.
import { afterAll, expect, it } from "vitest";
import { trialSamples } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

it("thins samples to at most one per slice of time, first of each, in order; the full series stays available", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  await db.insert(trialSamples).values(
    Array.from({ length: 1000 }, (_, i) => ({
      trialId: trial.id,
      topic: "/joint_states",
      relMs: i * 20,
      data: { position: [i] },
    })),
  );
  const thinned = await owner.trials.samples({ trialId: trial.id, topic: "/joint_states", maxPoints: 10 });
  expect(thinned.length).toBeLessThanOrEqual(11);
  expect(thinned.length).toBeGreaterThanOrEqual(10);
  expect(thinned[0]).toMatchObject({ relMs: 0, data: { position: [0] } });
  expect(thinned.map((s) => s.relMs)).toEqual([...thinned.map((s) => s.relMs)].sort((a, b) => a - b));
  expect(await owner.trials.samples({ trialId: trial.id, topic: "/joint_states" })).toHaveLength(1000);
});

it("thins an hour's samples as one sort of them all would: the first of each slice, with gaps, bursts and two topics", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  // An hour of joint states at 50 Hz with jitter, a minute-long gap and a burst of equal times; odometry at 10 Hz.
  const rows: Array<typeof trialSamples.$inferInsert> = [];
  for (let i = 0; i < 180_000; i++) {
    const relMs = i * 20 + ((i * 7919) % 13) / 3;
    if (relMs > 600_000 && relMs < 660_000) continue;
    rows.push({ trialId: trial.id, topic: "/joint_states", relMs: i < 50 ? 5 : relMs, data: { i } });
  }
  for (let i = 0; i < 36_000; i++) rows.push({ trialId: trial.id, topic: "/odom", relMs: i * 100 + 0.5, data: { i } });
  for (let start = 0; start < rows.length; start += 10_000)
    await db.insert(trialSamples).values(rows.slice(start, start + 10_000));
  // The thinning as one sort of every sample would give it (DISTINCT ON the slice), for each case.
  const sorted = async (maxPoints: number, topic?: string) => {
    const last = rows.reduce((m, r) => (!topic || r.topic === topic ? Math.max(m, r.relMs) : m), 0);
    const perMs = maxPoints / (last + 1);
    const result = await db.$client<Array<{ topic: string; rel_ms: number }>>`
      select distinct on (slice) topic, rel_ms from (
        select topic, rel_ms, floor(rel_ms * ${perMs}::float8) as slice from trial_samples
        where trial_id = ${trial.id} and (${topic ?? null}::text is null or topic = ${topic ?? null})
      ) as sample
      order by slice, rel_ms`;
    return result.map((r) => ({ topic: r.topic, relMs: r.rel_ms }));
  };
  for (const [maxPoints, topic] of [
    [2000, "/joint_states"],
    [10, "/joint_states"],
    [20_000, "/odom"],
    [2000, undefined],
  ] as const) {
    const thinned = await owner.trials.samples({ trialId: trial.id, maxPoints, ...(topic ? { topic } : {}) });
    const expected = await sorted(maxPoints, topic);
    expect(thinned.length, `${maxPoints} of ${topic ?? "every topic"}`).toBe(expected.length);
    // Equal times of two topics may come in either order: the topic is compared where only one was given.
    expect(thinned.map((s) => s.relMs)).toEqual(expected.map((s) => s.relMs));
    if (topic) expect(thinned.every((s) => s.topic === topic)).toBe(true);
    expect(thinned.length).toBeLessThanOrEqual(maxPoints);
  }
});
