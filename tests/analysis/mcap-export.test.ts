// A trial's MCAP file, read back by the reference reader from PyPI (mcap):
// the robot's state samples on their own topics, the commands sent to the
// robot and every trial event, each JSON with a JSON Schema (what Foxglove
// and Lichtblick need to show them), in time order from the trial's t0.
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, expect, it } from "vitest";
import { appendEvents } from "../../src/store/event-store";
import { trialSamples, trials } from "../../src/store/schema";
import { eq } from "drizzle-orm";
import { buildFixture, publishedVersion } from "../api/fixture";
import { freshDatabase } from "../support/db";
import { runPython } from "../support/python";
import { scratchRoot } from "../support/scratch";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);

it("holds the samples, the robot commands and the trial events as channels, with every message", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  const t0 = new Date("2026-01-05T10:00:00Z");
  await appendEvents(
    db,
    { id: trial.id, lastSeq: 0, t0: null },
    [
      { type: "trial.started" },
      {
        type: "action.requested",
        stepId: null,
        actionId: "u1",
        actionType: "say",
        parameters: { text: "Hello" },
        scripted: false,
        deviation: "unscripted",
      } as never,
      { type: "action.dispatched", actionId: "u1", detail: { topic: "/speech", message: { data: "Hello" } } },
      { type: "action.completed", actionId: "u1" },
      { type: "note.added", text: "Participant smiled" },
    ],
    f.people.wizard.id,
  );
  await db.update(trials).set({ t0 }).where(eq(trials.id, trial.id));
  await db.insert(trialSamples).values([
    ...Array.from({ length: 50 }, (_, i) => ({
      trialId: trial.id,
      topic: "/joint_states",
      relMs: i * 20,
      data: { name: ["HeadYaw"], position: [i / 10] },
    })),
    ...Array.from({ length: 3 }, (_, i) => ({
      trialId: trial.id,
      topic: "/battery_state",
      relMs: i * 500,
      data: { percentage: 0.9 - i / 100 },
    })),
  ]);

  const file = await owner.trials.export({ trialId: trial.id, format: "mcap" });
  expect(file).toMatchObject({ filename: `trial-${trial.id}.mcap`, contentType: "application/octet-stream" });
  const path = join(scratchRoot(), `trial-${trial.id}.mcap`);
  writeFileSync(path, file.body as Uint8Array);
  const read = JSON.parse(runPython("read_mcap.py", [path]));

  expect(read.library).toBe("HRIStudio");
  expect(Object.keys(read.channels).sort()).toEqual([
    "/battery_state",
    "/hristudio/events",
    "/hristudio/robot_commands",
    "/joint_states",
  ]);
  const json = { messageEncoding: "json", schemaEncoding: "jsonschema", ordered: true };
  expect(read.channels["/joint_states"]).toMatchObject({
    ...json,
    count: 50,
    first: { name: ["HeadYaw"], position: [0] },
    // Placed from t0, in nanoseconds.
    firstLogTime: t0.getTime() * 1_000_000,
  });
  expect(read.channels["/battery_state"]).toMatchObject({ ...json, count: 3, first: { percentage: 0.9 } });
  expect(read.channels["/hristudio/events"]).toMatchObject({ ...json, count: 5, first: { type: "trial.started" } });
  expect(read.channels["/hristudio/robot_commands"]).toMatchObject({
    ...json,
    count: 1,
    first: { type: "action.dispatched", detail: { topic: "/speech", message: { data: "Hello" } } },
  });
  expect(read.statistics).toBe(50 + 3 + 5 + 1);
});
