import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../plugins";
import { replaySchedule } from "./replay";
import type { EngineEvent, TrialEvent } from "./types";

const loaded = loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8"));
if (!loaded.ok) throw new Error("plugins/nao6-ros2.json does not load");
const nao: Plugin = loaded.value;

/** A log written as [relMs, event] pairs; sequence numbers follow the order given. */
const log = (...entries: Array<[number, EngineEvent]>): TrialEvent[] =>
  entries.map(([relMs, e], i) => ({ ...e, seq: i + 1, relMs }));
const requested = (actionId: string, actionType: string, parameters: Record<string, unknown> = {}): EngineEvent => ({
  type: "action.requested",
  stepId: "s1",
  actionId,
  actionType,
  parameters,
  scripted: true,
});
const dispatched = (actionId: string): EngineEvent => ({ type: "action.dispatched", actionId });
const completed = (actionId: string): EngineEvent => ({ type: "action.completed", actionId });

const say = (text: string) => ({
  kind: "publish",
  topic: "/speech",
  messageType: "std_msgs/msg/String",
  message: { data: text },
});
const gesture = (name: string) => ({
  kind: "publish",
  topic: "/animation",
  messageType: "std_msgs/msg/String",
  message: { data: `animations/Stand/Gestures/${name}` },
});

// A trial: hello at 1 s; wave and "look" together at 5 s (a parallel group,
// sent in the order the runtime dispatched them); a pause; goodbye at 12 s.
const trial = log(
  [0, { type: "trial.started" }],
  [0, { type: "step.entered", stepId: "s1", via: "start" }],
  [990, requested("hello", "say", { text: "Hello." })],
  [1000, dispatched("hello")],
  [1001, completed("hello")],
  [4990, requested("wave", "nao6-ros2.play_animation_hey")],
  [4990, requested("look", "say", { text: "Look!" })],
  [5000, dispatched("look")],
  [5004, dispatched("wave")],
  [6000, requested("hold", "pause", { seconds: 2 })],
  [6001, dispatched("hold")],
  [8001, completed("hold")],
  [11990, requested("bye", "nao6-ros2.say_text", { text: "Goodbye." })],
  [12000, dispatched("bye")],
  [12500, { type: "trial.completed" }],
);

const plan = (events: TrialEvent[], options: { fromMs?: number; speed?: number } = {}) =>
  replaySchedule(nao, events, options).commands.map((c) => [c.atMs, c.actionId, c.message]);

describe("a finished trial's robot commands, scheduled again", () => {
  it.each([
    [
      "from the start at ×1: every message in the order it left, at its dispatch time",
      {},
      [
        [1000, "hello", say("Hello.")],
        [5000, "look", say("Look!")],
        [5004, "wave", gesture("Hey_1")],
        [12000, "bye", say("Goodbye.")],
      ],
    ],
    [
      "at ×2: every gap halved",
      { speed: 2 },
      [
        [500, "hello", say("Hello.")],
        [2500, "look", say("Look!")],
        [2502, "wave", gesture("Hey_1")],
        [6000, "bye", say("Goodbye.")],
      ],
    ],
    [
      "at ×0.5: every gap doubled",
      { speed: 0.5 },
      [
        [2000, "hello", say("Hello.")],
        [10000, "look", say("Look!")],
        [10008, "wave", gesture("Hey_1")],
        [24000, "bye", say("Goodbye.")],
      ],
    ],
    [
      "from mid-trial: earlier commands left out, the rest timed from the starting point",
      { fromMs: 4000 },
      [
        [1000, "look", say("Look!")],
        [1004, "wave", gesture("Hey_1")],
        [8000, "bye", say("Goodbye.")],
      ],
    ],
    [
      "from mid-trial at ×2",
      { fromMs: 5000, speed: 2 },
      [
        [0, "look", say("Look!")],
        [2, "wave", gesture("Hey_1")],
        [3500, "bye", say("Goodbye.")],
      ],
    ],
    ["from after the last command: nothing", { fromMs: 12001 }, []],
  ])("%s", (_name, options, expected) => {
    expect(plan(trial, options)).toEqual(expected);
  });

  it("a trial with no robot commands (only the wizard's blocks) schedules nothing", () => {
    const quiet = log(
      [0, { type: "trial.started" }],
      [10, requested("note", "wizard_instruction", { text: "Smile" })],
      [20, requested("hold", "pause", { seconds: 1 })],
      [30, dispatched("hold")],
      [1030, completed("hold")],
      [1100, { type: "trial.completed" }],
    );
    expect(replaySchedule(nao, quiet)).toEqual({ commands: [], skipped: [], endMs: 1100 });
  });

  it("an action requested but never dispatched (failed before the robot) is not sent", () => {
    const failed = log(
      [0, { type: "trial.started" }],
      [10, requested("hello", "say", { text: "Hello." })],
      [20, { type: "action.failed", actionId: "hello", reason: "robot not connected" }],
    );
    expect(plan(failed)).toEqual([]);
  });

  it("a step entered again sends its action again, with the parameters of each request", () => {
    const again = log(
      [0, requested("ask", "say", { text: "Ready?" })],
      [10, dispatched("ask")],
      [3000, requested("ask", "say", { text: "Ready now?" })],
      [3010, dispatched("ask")],
    );
    expect(plan(again)).toEqual([
      [10, "ask", say("Ready?")],
      [3010, "ask", say("Ready now?")],
    ]);
  });

  it("an SSH posture is named as skipped, with why, and the rest still play", () => {
    const sat = log(
      [0, requested("sit", "nao6-ros2.sit")],
      [10, dispatched("sit")],
      [20, requested("hello", "say", { text: "Hello." })],
      [30, dispatched("hello")],
    );
    const schedule = replaySchedule(nao, sat);
    expect(schedule.commands.map((c) => c.actionId)).toEqual(["hello"]);
    expect(schedule.skipped).toEqual([
      { actionId: "sit", trialMs: 10, reason: '"Sit" went to the robot over SSH, not rosbridge' },
    ]);
  });

  it("keeps the plugin action and its filled-in parameters, so the transport sends exactly the same message", () => {
    const [command] = replaySchedule(nao, trial).commands;
    expect(command!.action.id).toBe("say_text");
    expect(command!.parameters).toEqual({ text: "Hello." });
  });
});
