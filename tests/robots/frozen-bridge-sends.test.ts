// What reaches a robot whose bridge froze (issue 25): the simulated robot
// runs as its own process and is stopped (SIGSTOP) for 10 s, then 30 s, while
// the wizard's says go out through the runtime's robot link. Whatever the
// trial would log as not sent or failed must never be spoken once the bridge
// goes on; a say the wizard sends again after being told is spoken once.
// What the robot said is read at the robot, by a listener of its own.
// Together the two freezes make this file about a minute long.
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import type { RobotLink, RobotReport } from "../../src/runtime/robot";
import { pluginRobot } from "../../src/runtime/robot-link";
import { listenToSpeech } from "../support/robot-ears";
import { type SimulatorProcess, startSimulatorProcess } from "../support/simulator-process";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;

let bridge: SimulatorProcess | null = null;
let robot: RobotLink | null = null;
let ears: Awaited<ReturnType<typeof listenToSpeech>> | null = null;
afterEach(() => {
  ears?.close();
  robot?.close();
  bridge?.kill();
  bridge = robot = ears = null;
  reports.clear();
});

const pause = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

/** Every report of each action, in order, as the trial would log them. */
const reports = new Map<string, RobotReport[]>();

/** A say asked for now, as the wizard's page would: its outcome, as the trial would log it. */
function say(link: RobotLink, text: string): Promise<RobotReport> {
  return new Promise((resolve) =>
    link.perform(
      { actionId: text, actionType: "nao6-ros2.say_text", parameters: { text }, askedAt: Date.now() },
      (report) => {
        reports.set(text, [...(reports.get(text) ?? []), report]);
        if (report.kind !== "dispatched") resolve(report);
      },
    ),
  );
}

describe.each([10_000, 30_000])("a bridge frozen for %i ms while says are sent", (freezeMs) => {
  it("speaks nothing reported not sent or failed, and a say sent again once", {
    timeout: freezeMs + 40_000,
  }, async () => {
    bridge = await startSimulatorProcess();
    ears = await listenToSpeech(bridge.url);
    const transport = new RosbridgeTransport({ url: bridge.url, backoffMs: { first: 100, max: 200 } });
    robot = pluginRobot(nao, transport);
    expect(await say(robot, "before")).toMatchObject({ kind: "completed" });

    bridge.freeze();
    const frozenAt = Date.now();
    // Sent as it froze, and into the hang before the loss is found: each left for the robot.
    const asItFroze = say(robot, "as it froze");
    await pause(600);
    const intoTheHang = say(robot, "into the hang");
    await expect.poll(() => transport.health().state, { timeout: 5000 }).not.toBe("connected");
    // Sent once the loss is known: the link waits for the robot only while the say is worth doing.
    const afterTheLoss = await say(robot, "after the loss");
    expect(afterTheLoss).toMatchObject({ kind: "not_sent" });

    const outcomes = [await asItFroze, await intoTheHang, afterTheLoss];
    await pause(Math.max(0, frozenAt + freezeMs - Date.now()));
    bridge.thaw();
    await expect.poll(() => transport.health().state, { timeout: 15_000 }).toBe("connected");

    // The wizard, told "after the loss" was not sent, asks for it again; then one last say closes the run.
    expect(await say(robot, "after the loss")).toMatchObject({ kind: "completed" });
    expect(await say(robot, "last")).toMatchObject({ kind: "completed" });
    const heard = ears.take();
    expect(heard.filter((text) => text === "after the loss")).toHaveLength(1);
    for (const [text, outcome] of [
      ["as it froze", outcomes[0]],
      ["into the hang", outcomes[1]],
    ] as const) {
      // Never called failed or not sent and then spoken: at most "sent, outcome unknown".
      expect(["unknown", "completed"]).toContain(outcome!.kind);
      expect(heard.filter((h) => h === text).length).toBeLessThanOrEqual(1);
      // Spoken once the bridge went on: the robot's done message for it is told after the unknown, against it.
      if (outcome!.kind === "unknown" && heard.includes(text))
        await expect.poll(() => reports.get(text)!.map((r) => r.kind)).toEqual(["dispatched", "unknown", "completed"]);
    }
    expect(heard.at(-1)).toBe("last");
  });
});
