// The robots admin page's health of a robot in a live trial carries what the
// robot's side reported (a silent topic, a refused subscription), read from
// that trial's log: the last few different ones, and none once the trial ends.
import { eq } from "drizzle-orm";
import { afterAll, expect, it } from "vitest";
import { appendEvents } from "../../src/store/event-store";
import { trials } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture, publishedVersion } from "./fixture";

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
const admin = f.api("admin");
afterAll(close);

const SILENT =
  "The robot never sent /joint_states (expected about every 0.1 s): the bridge refused its type sensor_msgs/msg/JointState — a ROS 1 bridge names it sensor_msgs/JointState.";

it("shows the problems the robot's side reported during its live trial, in the log's words", async () => {
  const study = await f.newStudy("Robot study");
  const { version } = await publishedVersion(owner, study.id);
  const robot = await admin.robots.register({ name: "NAO on a ROS 1 bridge", rosbridgeUrl: "ws://192.0.2.10:9090" });
  const idle = await admin.robots.register({ name: "NAO on the shelf", rosbridgeUrl: "ws://192.0.2.11:9090" });
  const trial = await owner.trials.create({ versionId: version.id, wizardId: f.people.wizard.id });
  await db.update(trials).set({ assignedRobotId: robot.id }).where(eq(trials.id, trial.id));
  let at = { id: trial.id, lastSeq: 0, t0: null as Date | null };
  const append = async (events: Parameters<typeof appendEvents>[2]) => {
    const stored = await appendEvents(db, at, events, f.people.wizard.id);
    at = { ...at, lastSeq: at.lastSeq + events.length, t0: at.t0 ?? new Date() };
    return stored;
  };
  await append([{ type: "trial.started" }]);
  const texts = ["motor warm", SILENT, "battery low", "battery low", "camera unplugged"];
  await append(texts.map((text) => ({ type: "robot.problem" as const, text })));
  const problemsOf = async (id: string) => (await admin.robots.list()).find((r) => r.id === id)!.problems;
  // The last three different ones, oldest first, a repeat once: the trial's log keeps them all.
  expect(await problemsOf(robot.id)).toEqual([SILENT, "battery low", "camera unplugged"]);
  expect(await problemsOf(idle.id)).toEqual([]);

  await append([{ type: "trial.completed" }]);
  expect(await problemsOf(robot.id)).toEqual([]);
});
