// Robots as records, driven by the real runtime process (PostgreSQL, the
// runtime, two simulated robots over real sockets, the real roslib client):
// two trials drive two robots at once, each wizard told its robot's name
// before starting; a second live trial on a robot is refused in plain words
// naming the trial that holds it, by the runtime and by the database; the
// robot's health reaches its record and its live state the wizard's page,
// and a runtime that stops leaves each record saying disconnected.
import type { ChildProcess } from "node:child_process";
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { createAccount } from "../../src/server/auth/accounts";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { isRobotTakenError } from "../../src/robots/registry";
import { createDatabase } from "../../src/store/client";
import {
  experimentVersions,
  experiments,
  participants,
  robots,
  studies,
  studyMembers,
  trials,
} from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { registerRobots } from "../support/robots";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";

const SECRET = "robot-registry-test-secret".padEnd(40, "x");
const plugin = firstPartyPlugin("simulated.json");

const saying = (text: string): ProtocolSnapshot => ({
  schemaVersion: 5,
  experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
  steps: [
    {
      id: "s1",
      name: "Greeting",
      description: "",
      actions: [{ id: "hi", type: "say", name: "", parameters: { text }, parallelGroup: null }],
    },
  ],
});

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
const sims: Simulator[] = [];
const sockets: TrialSocket[] = [];
let runtime: { url: string; child: ChildProcess };
let wizardId: string;
let studyId: string;
const robotIds: Record<string, string> = {};

async function newTrial(text: string, code: string) {
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId, name: `Greeting ${code}`, robotId: "simulated" })
    .returning();
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot: saying(text), hash: code, robotId: "simulated" })
    .returning();
  const [participant] = await db.insert(participants).values({ studyId, code }).returning();
  const [trial] = await db
    .insert(trials)
    .values({
      studyId,
      experimentId: experiment!.id,
      versionId: version!.id,
      participantId: participant!.id,
      wizardId,
    })
    .returning();
  return trial!.id;
}

async function open(trialId: string) {
  const socket = await connectTrial(runtime.url, signSocketToken({ userId: wizardId, trialId }, SECRET));
  sockets.push(socket);
  return socket;
}

const spoken = (sim: Simulator) =>
  sim.received
    .filter((r) => r.message.op === "publish" && r.message.topic === "/speech")
    .map((r) => (r.message.msg as { data: string }).data);

beforeAll(async () => {
  for (let i = 0; i < 2; i++) sims.push(await startSimulator({ port: 0, nodes: simulatedRobot(plugin) }));
  const [study] = await db.insert(studies).values({ title: "Two robots", status: "active" }).returning();
  studyId = study!.id;
  wizardId = (
    await createAccount(db, { name: "Wizard", email: "w@example.org", password: "password-123", role: "researcher" })
  ).id;
  await db.insert(studyMembers).values({ studyId, userId: wizardId, role: "wizard" });
  for (const robot of await registerRobots(db, studyId, ["Sim A", "Sim B"], (i) => sims[i]!))
    robotIds[robot.name] = robot.id;
  // Registered, but not available to this study: never chosen for its trials.
  await db.insert(robots).values({ name: "Elsewhere", simulated: true, rosbridgeUrl: sims[0]!.url });
  runtime = await startRuntime(url, SECRET);
}, 120_000);

afterAll(async () => {
  for (const s of sockets) s.close();
  runtime?.child.kill("SIGKILL");
  for (const sim of sims) await sim.close();
  await close();
});

describe("robots as records, in the runtime", () => {
  let one: TrialSocket;
  let two: TrialSocket;
  let first: string;

  it("gives two trials opened at once two robots, each named to its wizard before starting, and drives both at once", {
    timeout: 60_000,
  }, async () => {
    first = await newTrial("Hello from trial one", "P1");
    const second = await newTrial("Hello from trial two", "P2");
    // Opened at the same moment: each must still take a robot the other has not.
    [one, two] = await Promise.all([open(first), open(second)]);
    const named = async (s: TrialSocket) => (await s.next((m) => m.type === "robot" && "name" in m)).name;
    const names = [await named(one), await named(two)];
    expect(names.sort()).toEqual(["Sim A", "Sim B"]);

    const results = await Promise.all([one.command("a1", { kind: "start" }), two.command("b1", { kind: "start" })]);
    expect(results.map((r) => r.type)).toEqual(["ack", "ack"]);
    await Promise.all([one.command("a2", { kind: "next" }), two.command("b2", { kind: "next" })]);

    const simOf = async (trialId: string) => {
      const [row] = await db.select({ robot: trials.assignedRobotId }).from(trials).where(eq(trials.id, trialId));
      return row!.robot === robotIds["Sim A"] ? sims[0]! : sims[1]!;
    };
    await expect.poll(async () => spoken(await simOf(first))).toEqual(["Hello from trial one"]);
    await expect.poll(async () => spoken(await simOf(second))).toEqual(["Hello from trial two"]);
  });

  it("refuses a second live trial on a robot, naming the trial that holds it", { timeout: 60_000 }, async () => {
    const [held] = await db.select({ robot: trials.assignedRobotId }).from(trials).where(eq(trials.id, first));
    const [robot] = await db.select().from(robots).where(eq(robots.id, held!.robot!));
    const third = await newTrial("Hello from trial three", "P3");
    await db.update(trials).set({ assignedRobotId: robot!.id }).where(eq(trials.id, third));
    const three = await open(third);
    const refused = await three.command("c1", { kind: "start" });
    expect(refused.type).toBe("rejected");
    expect(refused.reason).toContain(`The robot "${robot!.name}" is being driven by another live trial`);
    expect(refused.reason).toContain('the trial of "Greeting P1" with participant P1, in progress');
    const [status] = await db.select({ status: trials.status }).from(trials).where(eq(trials.id, third));
    expect(status!.status).toBe("scheduled");
    expect(spoken(sims[0]!).concat(spoken(sims[1]!))).not.toContain("Hello from trial three");

    // The database refuses it too, whichever process would write it.
    const write = db.update(trials).set({ status: "in_progress" }).where(eq(trials.id, third));
    await expect(write).rejects.toSatisfy(isRobotTakenError);
  });

  it("writes each robot's health to its record, and sends the wizard what the robot is doing", {
    timeout: 60_000,
  }, async () => {
    await expect
      .poll(async () =>
        (await db.select().from(robots).where(eq(robots.id, robotIds["Sim A"]!))).map((r) => [
          r.connected,
          r.lastSeenAt !== null,
        ]),
      )
      .toEqual([[true, true]]);
    // The battery and the robot's own report arrive on two topics, in either order.
    const state = await one.next((m) => m.type === "robotState" && m.battery !== null && m.posture !== null);
    expect(state).toMatchObject({ posture: "stand" });
    expect(state.battery).toBeGreaterThan(90);
    // While the robot spoke the trial's line, the wizard was told so, with its text.
    await one.next((m) => m.type === "robotState" && m.speaking === "Hello from trial one");
  });

  it("stopping, says on each robot's record that it is no longer connected, and logs no error doing so", {
    timeout: 60_000,
  }, async () => {
    let logged = "";
    runtime.child.stderr!.on("data", (d) => (logged += String(d)));
    const exited = new Promise((ok) => runtime.child.once("exit", ok));
    runtime.child.kill("SIGTERM");
    await exited;
    const records = await db.select({ name: robots.name, connected: robots.connected }).from(robots);
    expect(records.filter((r) => r.name !== "Elsewhere").map((r) => r.connected)).toEqual([false, false]);
    expect(logged).not.toContain("[hristudio] error");
  });
});
