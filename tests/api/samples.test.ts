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
