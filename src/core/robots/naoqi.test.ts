import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, shellCommand, type Plugin } from "../plugins";
import { naoqiCommand, type NaoqiReply } from "./naoqi";

const plugin = (file: string) =>
  (loadPlugin(file, readFileSync(`plugins/${file}`, "utf8")) as { ok: true; value: Plugin }).value;

/** Every SSH command of a plugin, built and quoted exactly as the SSH transport sends it. */
const sshCommands = (file: string) =>
  plugin(file).actions.flatMap((action) => {
    const mapping = action.ros2 && "payloadMapping" in action.ros2 ? action.ros2.payloadMapping : null;
    if (mapping?.type !== "ssh") return [];
    const built = shellCommand(mapping.sshCommand, {});
    if (!built.ok) throw new Error(built.reason);
    return [[action.id, built.command] as const];
  });

describe("the simulated NAO's answers to qicli over SSH", () => {
  it.each<[string, Partial<NaoqiReply>]>([
    ["qicli call ALMotion.wakeUp", { exitCode: 0, stdout: "", change: { awake: true, posture: "stand" } }],
    ["'qicli' 'call' 'ALMotion.rest'", { exitCode: 0, change: { awake: false, posture: "rest" } }],
    [
      "'qicli' 'call' 'ALRobotPosture.goToPosture' 'Sit' '0.5'",
      { exitCode: 0, stdout: "true\n", change: { awake: true, posture: "sit" } },
    ],
    [
      "qicli call ALRobotPosture.goToPosture StandInit 1",
      { exitCode: 0, change: { awake: true, posture: "stand init" } },
    ],
    ["qicli call ALRobotPosture.goToPosture LyingBack 0.2", { change: { awake: true, posture: "lying on its back" } }],
    ["", { exitCode: 0, change: {} }],
  ])("%j", (command, reply) => {
    expect(naoqiCommand(command)).toMatchObject({ stderr: "", ...reply });
  });

  it.each<[string, number, string]>([
    [
      "qicli call ALRobotPosture.goToPosture Dance 0.5",
      1,
      'ALRobotPosture.goToPosture: no posture "Dance" (the robot knows Stand, StandInit, StandZero, Sit, SitRelax, Crouch, LyingBelly, LyingBack)',
    ],
    [
      "qicli call ALRobotPosture.goToPosture Sit",
      1,
      'ALRobotPosture.goToPosture: the speed must be a number above 0 and at most 1, not ""',
    ],
    [
      "qicli call ALRobotPosture.goToPosture Sit fast",
      1,
      'ALRobotPosture.goToPosture: the speed must be a number above 0 and at most 1, not "fast"',
    ],
    [
      "qicli call ALLeds.fadeRGB",
      1,
      "qicli: the simulated robot has no method ALLeds.fadeRGB (it offers ALMotion.wakeUp, ALMotion.rest, ALRobotPosture.goToPosture)",
    ],
    ["qicli info ALMotion", 1, "qicli: the simulated robot answers only `qicli call Service.method ...`"],
    ["reboot", 127, "sh: reboot: not found (the simulated robot has only qicli)"],
    [
      "qicli call ALMotion.rest; reboot",
      2,
      'sh: the simulated robot runs one plain command: ";" asks the shell for more than one plain command',
    ],
  ])("refuses %j with exit %i: %s", (command, exitCode, stderr) => {
    expect(naoqiCommand(command)).toEqual({ exitCode, stdout: "", stderr: `${stderr}\n`, change: {} });
  });

  it.each(["nao6-ros2.json", "pepper-ros2.json"])("carries out every SSH command of %s", (file) => {
    const commands = sshCommands(file);
    expect(commands.length).toBeGreaterThan(0);
    for (const [id, command] of commands) expect([id, naoqiCommand(command).exitCode]).toEqual([id, 0]);
  });
});
