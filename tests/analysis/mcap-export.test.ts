// A trial's MCAP file in Foxglove's terms, read back by the reference reader
// from PyPI (mcap) and checked as `mcap doctor` would (CRCs, summary counts),
// every message against its channel's JSON Schema (jsonschema from PyPI):
// the robot's state samples on their own topics with schemas of their fields
// named for the ROS types the plugin declares (joint states as
// sensor_msgs/msg/JointState), the robot's JSON state report as
// numbers a chart can plot, trial events as foxglove.Log, and times in whole
// nanoseconds from the trial's t0. (Foxglove's own CLIs are in no registry
// this machine reaches: the Go module proxy refuses github.com/foxglove/mcap/go/cli/mcap
// and the Rust CLI is not published to crates.io.)
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, expect, it } from "vitest";
import { appendEvents } from "../../src/store/event-store";
import { trialSamples, trials } from "../../src/store/schema";
import { buildFixture, publishedVersion } from "../api/fixture";
import { freshDatabase } from "../support/db";
import { pythonEnvironment, runPython } from "../support/python";
import { scratchRoot } from "../support/scratch";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
afterAll(close);
// The reference tools install on first use, longer than a test may take.
beforeAll(() => void pythonEnvironment(), 900_000);

it("holds samples, joint states, robot state, commands and events with real schemas, each message valid, at whole nanoseconds", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  // A t0 with milliseconds: epoch nanoseconds past 2^53 are where float arithmetic was off.
  const t0 = new Date("2026-01-05T10:00:00.123Z");
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
      { type: "robot.problem", text: "The bridge dropped /battery" },
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
      data: {
        header: { stamp: { sec: 1, nanosec: i }, frame_id: "base_link" },
        name: ["HeadYaw", "HeadPitch"],
        position: [i / 10, -0.5],
        velocity: [0.1, 0],
        effort: [],
      },
    })),
    ...Array.from({ length: 3 }, (_, i) => ({
      trialId: trial.id,
      topic: "/battery",
      relMs: i * 500,
      data: { percentage: 0.9 - i / 100 },
    })),
    // The simulated robot's report: a std_msgs/String holding JSON.
    ...Array.from({ length: 2 }, (_, i) => ({
      trialId: trial.id,
      topic: "/hristudio/robot_state",
      relMs: 100 + i,
      data: { data: JSON.stringify({ posture: "stand", awake: true, speed: i * 0.5 }) },
    })),
  ]);

  const file = await owner.trials.export({ trialId: trial.id, format: "mcap" });
  expect(file).toMatchObject({ filename: `trial-${trial.id}.mcap`, contentType: "application/octet-stream" });
  const path = join(scratchRoot(), `trial-${trial.id}.mcap`);
  writeFileSync(path, file.body as Uint8Array);
  const read = JSON.parse(runPython("read_mcap.py", [path]));

  expect(read.problems).toEqual([]);
  expect(read.library).toBe("HRIStudio");
  expect(Object.keys(read.channels).sort()).toEqual([
    "/battery",
    "/hristudio/events",
    "/hristudio/robot_commands",
    "/hristudio/robot_state",
    "/joint_states",
  ]);
  // One schema per shape: five shapes, five schemas, each with its fields.
  const names = read.schemas.map((s: { name: string }) => s.name).sort();
  expect(names).toEqual([
    "foxglove.Log",
    "hristudio.RobotCommand",
    "hristudio.robot.hristudio.robot_state",
    "sensor_msgs/msg/BatteryState",
    "sensor_msgs/msg/JointState",
  ]);
  for (const s of read.schemas) expect(Object.keys(s.schema.properties ?? {}).length, s.name).toBeGreaterThan(0);
  const json = { messageEncoding: "json", schemaEncoding: "jsonschema", ordered: true, publishedWhenLogged: true };

  const joints = read.channels["/joint_states"];
  expect(joints).toMatchObject({ ...json, schemaName: "sensor_msgs/msg/JointState", count: 50 });
  expect(joints.messages[3]).toMatchObject({ name: ["HeadYaw", "HeadPitch"], position: [0.3, -0.5] });
  const jointSchema = read.schemas.find((s: { name: string }) => s.name === "sensor_msgs/msg/JointState").schema;
  expect(jointSchema.properties).toMatchObject({
    name: { type: "array", items: { type: "string" } },
    position: { type: "array", items: { type: "number" } },
    header: { type: "object", properties: { stamp: { type: "object" }, frame_id: { type: "string" } } },
  });
  // Placed from t0 in whole nanoseconds: the stored milliseconds times 10^6, exactly.
  const at = (relMs: number) => String(BigInt(t0.getTime() + relMs) * 1_000_000n);
  expect(joints.logTimes.slice(0, 3)).toEqual([at(0), at(20), at(40)]);
  expect(joints.logTimes[49]).toBe(at(980));

  expect(read.channels["/battery"]).toMatchObject({ ...json, count: 3, messages: [{ percentage: 0.9 }, {}, {}] });
  expect(read.channels["/battery"].logTimes).toEqual([at(0), at(500), at(1000)]);

  // The robot's state report as fields a chart plots: numbers are numbers.
  const state = read.channels["/hristudio/robot_state"];
  expect(state).toMatchObject({
    ...json,
    count: 2,
    messages: [{ posture: "stand", awake: true, speed: 0 }, { speed: 0.5 }],
  });
  const stateSchema = read.schemas.find((s: { id: number }) => s.id === state.schemaId).schema;
  expect(stateSchema.properties.speed).toEqual({ type: "number" });

  const events = read.channels["/hristudio/events"];
  expect(events).toMatchObject({ ...json, schemaName: "foxglove.Log", count: 6 });
  expect(events.messages.map((m: { message: string }) => m.message.split(" ")[0])).toEqual([
    "trial.started",
    "action.requested",
    "action.dispatched",
    "action.completed",
    "robot.problem",
    "note.added",
  ]);
  // INFO, WARNING off script and for the robot's problem.
  expect(events.messages.map((m: { level: number }) => m.level)).toEqual([2, 3, 2, 2, 3, 2]);
  expect(events.messages[5].message).toContain("Participant smiled");
  events.messages.forEach((m: { timestamp: { sec: number; nsec: number } }, i: number) =>
    expect(String(BigInt(m.timestamp.sec) * 1_000_000_000n + BigInt(m.timestamp.nsec))).toBe(events.logTimes[i]),
  );

  expect(read.channels["/hristudio/robot_commands"]).toMatchObject({
    ...json,
    schemaName: "hristudio.RobotCommand",
    count: 1,
    messages: [{ type: "action.dispatched", detail: { topic: "/speech", message: { data: "Hello" } } }],
  });
  expect(read.statistics).toBe(50 + 3 + 2 + 6 + 1);
});
