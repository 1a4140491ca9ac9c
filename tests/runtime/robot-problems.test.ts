// What the robot's bridge reports goes into the trial's log and to the
// wizard: a state subscription or an action's advertise the bridge refuses
// (a type it does not know) and the bridge's own status frames. The real runtime parts over a real
// socket: the NAO6 plugin through roslib (RosbridgeTransport, pluginRobot)
// to the simulated robot, told to send protocol.md's status frames, and a
// trial host writing to a real database.
import { readFileSync } from "node:fs";
import { afterAll, afterEach, describe, expect, it } from "vitest";
import { eventRows } from "../../src/core/analysis/exports";
import { trialNames } from "../../src/core/analysis/names";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import type { TrialProtocol } from "../../src/core/trial";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { pluginRobot } from "../../src/runtime/robot-link";
import { TrialHost } from "../../src/runtime/trial-host";
import { eventsSince } from "../../src/store/event-store";
import { bareTrial, freshDatabase } from "../support/db";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
// The plugin as a researcher might have written it: one state topic of a type the bridge does not know.
const plugin: Plugin = {
  ...nao,
  stateTopics: [...(nao.stateTopics ?? []), { topic: "/mood", messageType: "no_such_msgs/msg/Mood" }],
};
const protocol: TrialProtocol = {
  steps: [{ id: "s1", name: "One", actions: [{ id: "hi", type: "say", parameters: { text: "hi" } }] }],
};

describe("problems the robot's bridge reports", async () => {
  const { db, close } = await freshDatabase();
  afterAll(close);
  let sim: Simulator | null = null;
  let host: TrialHost | null = null;
  afterEach(async () => {
    await host?.close();
    await sim?.close();
    host = sim = null;
  });

  async function open(drives = plugin) {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { msPerChar: 1 }), statusFrames: true });
    const trialId = await bareTrial(db);
    const robot = pluginRobot(drives, new RosbridgeTransport({ url: sim.url }));
    // What the wizard is told (the host's onRobotStatus is the link's onConnection), heard from the first
    // moment: a refusal can come while the host is still reading the log, before a listener of the host's.
    const wizard: string[] = [];
    robot.onConnection((_, detail) => detail && wizard.push(detail));
    host = await TrialHost.open(db, trialId, protocol, robot);
    const problems = async () =>
      (await eventsSince(db, trialId)).flatMap((e) => (e.type === "robot.problem" ? [e.text] : []));
    return { trialId, wizard, problems };
  }

  it("a refused state subscription is logged as the robot's problem, shown to the wizard and exported", async () => {
    const { trialId, wizard, problems } = await open();
    await expect.poll(problems, { timeout: 15_000 }).toHaveLength(1);
    const [text] = await problems();
    // Said as what the wizard will miss: the topic, what was expected, and the bridge's words.
    expect(text).toBe(
      "The robot never sent /mood (expected about every 1 s): the bridge refused to subscribe to it as no_such_msgs/msg/Mood: Unable to load the manifest for package no_such_msgs.",
    );
    expect(wizard).toContain(text);
    // The other state topics still flow: the problem is the one subscription, not the link.
    expect(sim!.received.filter((r) => r.message.op === "subscribe").map((r) => r.message.topic)).toEqual(
      expect.arrayContaining(["/joint_states", "/battery", "/mood"]),
    );
    const events = await eventsSince(db, trialId);
    const rows = eventRows(trialId, events, { wizard: null, createdBy: null }, trialNames(protocol, events));
    const row = rows.find((r) => r[4] === "robot.problem")!;
    expect(JSON.parse(String(row.at(-1)))).toMatchObject({ type: "robot.problem", text });
  });

  it("a refused advertise of an action's topic is logged during the trial", async () => {
    // The say action's message type misspelt: the bridge refuses roslib's advertise of /speech.
    const misspelt: Plugin = {
      ...plugin,
      actions: nao.actions.map((a) =>
        a.id === "say_text" && a.ros2 ? { ...a, ros2: { ...a.ros2, messageType: "no_such_msgs/msg/Words" } } : a,
      ),
    };
    const { problems } = await open(misspelt);
    await expect.poll(problems, { timeout: 15_000 }).toHaveLength(1);
    expect((await host!.command({ kind: "start" }, null)).ok).toBe(true);
    expect((await host!.command({ kind: "next" }, null)).ok).toBe(true);
    await expect.poll(problems, { timeout: 15_000 }).toHaveLength(2);
    expect((await problems())[1]).toBe(
      "The robot's bridge refused to carry /speech as no_such_msgs/msg/Words: Unable to load the manifest for package no_such_msgs.",
    );
    expect(sim!.received.find((r) => r.message.op === "advertise" && r.message.topic === "/speech")?.message.type).toBe(
      "no_such_msgs/msg/Words",
    );
  });

  it("status frames of level error and warning are logged in order, the same one told again in a row once; info is not", async () => {
    const { problems } = await open();
    await expect.poll(problems, { timeout: 15_000 }).toHaveLength(1);
    sim!.faults.reportStatus("warning", "battery low");
    sim!.faults.reportStatus("warning", "battery low");
    sim!.faults.reportStatus("info", "all is well");
    sim!.faults.reportStatus("error", "left arm motor overheating");
    await expect.poll(problems).toHaveLength(3);
    expect((await problems()).slice(1)).toEqual([
      "the robot's bridge reported a warning: battery low",
      "the robot's bridge reported an error: left arm motor overheating",
    ]);
  });

  it("a problem reported during the trial is in its log with the trial's time; none after it ended", async () => {
    const { trialId, wizard, problems } = await open();
    await expect.poll(problems, { timeout: 15_000 }).toHaveLength(1);
    expect((await host!.command({ kind: "start" }, null)).ok).toBe(true);
    sim!.faults.reportStatus("error", "camera unplugged");
    await expect.poll(problems).toHaveLength(2);
    const during = (await eventsSince(db, trialId)).find(
      (e) => e.type === "robot.problem" && e.text.includes("camera"),
    );
    expect(during?.relMs).toBeGreaterThanOrEqual(0);
    expect((await host!.command({ kind: "abort", reason: "done" }, null)).ok).toBe(true);
    sim!.faults.reportStatus("error", "after the end");
    // The wizard is told after the host's log was asked; a note asked for next is logged after it would have been.
    await expect.poll(() => wizard.some((d) => d.includes("after the end"))).toBe(true);
    expect((await host!.command({ kind: "note", text: "marker" }, null)).ok).toBe(true);
    expect(await problems()).toHaveLength(2);
  });
});
