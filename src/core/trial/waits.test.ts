import { describe, expect, it } from "vitest";
import { decide, fold, rehearse, simulate, type Command, type EngineEvent, type TrialProtocol } from "./index";

// "Touch my head to start": head touched → Greet, heard "ready" → the end, 20 s → Prompt; go on → Goodbye (the step's way on).
const protocol: TrialProtocol = {
  steps: [
    {
      id: "ask",
      name: "Ask",
      actions: [
        { id: "say", type: "say", parameters: { text: "Touch my head to start." } },
        {
          id: "wait",
          type: "wait_for",
          parameters: {
            events: [
              { id: "touch", event: "head_touched", after: { to: "step", stepId: "greet" } },
              { id: "ready", event: "heard_ready", after: { to: "end" } },
            ],
          },
          timeLimit: { seconds: 20, after: { to: "step", stepId: "prompt" } },
        },
      ],
    },
    { id: "bye", name: "Goodbye", after: { to: "end" }, actions: [] },
    { id: "greet", name: "Greet", after: { to: "end" }, actions: [] },
    { id: "prompt", name: "Prompt", after: { to: "end" }, actions: [] },
  ],
};

// The same wait with a line after it: go on carries on in the step.
const followed: TrialProtocol = {
  steps: [
    { ...protocol.steps[0]!, actions: [...protocol.steps[0]!.actions, { id: "more", type: "nod", parameters: {} }] },
  ],
};

const TIMER = "wait:wait:1";
const waiting: Command[] = [
  { kind: "start" },
  { kind: "next" },
  { kind: "dispatched", actionId: "say" },
  { kind: "completed", actionId: "say" },
];
const touch: Command = { kind: "sensed", event: "head_touched", at: 1_700_000_000_123, message: { data: true } };
const heard: Command = { kind: "sensed", event: "heard_ready", at: 1_700_000_000_456, message: { word: "ready" } };
const other: Command = { kind: "sensed", event: "left_hand_touched", at: 1_700_000_000_789, message: { data: true } };

const brief = (events: EngineEvent[] | string) =>
  typeof events === "string"
    ? events
    : events.map((e) => {
        if (e.type === "robot.sensed") return [e.type, e.event, e.at];
        if (e.type === "wait.resolved") return [e.type, e.by, e.event ?? null];
        if (e.type === "step.entered") return [e.type, e.stepId, e.via];
        if (e.type.startsWith("timer.")) return [e.type, (e as { timerId: string }).timerId];
        return [e.type, "actionId" in e ? e.actionId : null, e.deviation ?? null];
      });

describe("Wait for", () => {
  it.each<[string, TrialProtocol, Command[], unknown]>([
    [
      "the wait's clock starts once the line before it is done",
      protocol,
      waiting,
      [
        ["action.completed", "say", null],
        ["timer.started", TIMER],
      ],
    ],
    [
      "an awaited event takes its edge, with the robot's time, and cancels the clock",
      protocol,
      [...waiting, touch],
      [
        ["robot.sensed", "head_touched", 1_700_000_000_123],
        ["wait.resolved", "sensed", "head_touched"],
        ["step.entered", "greet", "sensed"],
        ["timer.cancelled", TIMER],
      ],
    ],
    [
      "another awaited event takes its own edge: here, the end",
      protocol,
      [...waiting, heard],
      [
        ["robot.sensed", "heard_ready", 1_700_000_000_456],
        ["wait.resolved", "sensed", "heard_ready"],
        ["trial.completed", null, null],
        ["timer.cancelled", TIMER],
      ],
    ],
    [
      "an event the wait does not list is an observation and changes nothing",
      protocol,
      [...waiting, other],
      [["robot.sensed", "left_hand_touched", 1_700_000_000_789]],
    ],
    [
      "an event while nothing waits (the line still running) is an observation",
      protocol,
      [...waiting.slice(0, 3), touch],
      [["robot.sensed", "head_touched", 1_700_000_000_123]],
    ],
    [
      "an event before the start is an observation",
      protocol,
      [touch],
      [["robot.sensed", "head_touched", 1_700_000_000_123]],
    ],
    [
      "an event while the trial is paused is an observation: the wizard paused it",
      protocol,
      [...waiting, { kind: "pause" }, touch],
      [["robot.sensed", "head_touched", 1_700_000_000_123]],
    ],
    [
      "the wizard's go on takes the step's own way on when nothing follows the wait, not a deviation",
      protocol,
      [...waiting, { kind: "go_on" }],
      [
        ["wait.resolved", "wizard", null],
        ["step.entered", "bye", "go_on"],
        ["timer.cancelled", TIMER],
      ],
    ],
    [
      "the wizard's go on carries on with what follows the wait in its step",
      followed,
      [...waiting, { kind: "go_on" }],
      [
        ["wait.resolved", "wizard", null],
        ["timer.cancelled", TIMER],
      ],
    ],
    [
      "next does not pass a pending wait",
      protocol,
      [...waiting, { kind: "next" }],
      "The trial waits for the robot to sense “head_touched” or “heard_ready”: go on to move on without it.",
    ],
    [
      "go on with nothing waiting is refused",
      protocol,
      [...waiting.slice(0, 3), { kind: "go_on" }],
      "Nothing is waiting for the robot now: the wait is already over.",
    ],
    [
      "race: the event first, then the wizard's go on: the go on changes nothing",
      protocol,
      [...waiting, touch, { kind: "go_on" }],
      "Nothing is waiting for the robot now: the wait is already over.",
    ],
    [
      "race: the go on first, then the event: the event is an observation only",
      protocol,
      [...waiting, { kind: "go_on" }, touch],
      [["robot.sensed", "head_touched", 1_700_000_000_123]],
    ],
    [
      "race: the time limit first, then the event: the event is an observation only",
      protocol,
      [...waiting, { kind: "timer_fired", timerId: TIMER }, touch],
      [["robot.sensed", "head_touched", 1_700_000_000_123]],
    ],
    [
      "race: the event first, then the time limit: the timer fires no more",
      protocol,
      [...waiting, touch, { kind: "timer_fired", timerId: TIMER }],
      "That timer is no longer running: the wizard acted first, or it fired.",
    ],
    [
      "the time limit takes its own edge, as a timer does",
      protocol,
      [...waiting, { kind: "timer_fired", timerId: TIMER }],
      [
        ["timer.fired", TIMER],
        ["step.entered", "prompt", "timeout"],
      ],
    ],
  ])("%s", (_, design, commands, expected) => {
    expect(brief(simulate(design, commands).last)).toEqual(expected);
  });

  it("an event after the end is refused: the trial's log is closed", () => {
    const { log } = simulate(protocol, [...waiting, heard]);
    expect(decide(protocol, fold(protocol, log), touch)).toEqual({
      ok: false,
      reason: "This trial has already ended.",
    });
  });

  it.each([
    [
      "by its plugin's names",
      { head_touched: "Head touched", heard_ready: 'Heard "ready"' },
      'The trial waits for the robot to sense “Head touched” or “Heard "ready"”: go on to move on without it.',
    ],
    [
      "by id where the plugin names none",
      { head_touched: "Head touched" },
      "The trial waits for the robot to sense “Head touched” or “heard_ready”: go on to move on without it.",
    ],
  ])("next at a pending wait names the awaited events %s", (_, names, reason) => {
    const { log } = simulate(protocol, waiting);
    expect(decide(protocol, fold(protocol, log), { kind: "next" }, names)).toEqual({ ok: false, reason });
  });

  it("keeps the message that matched in the log", () => {
    const { log } = simulate(protocol, [...waiting, touch]);
    expect(log.find((e) => e.type === "robot.sensed")).toMatchObject({ message: { data: true } });
  });

  it.each([
    ["nothing chosen: the wizard's go on", {}, [], ["ask", "bye"], undefined],
    ["the head touched: its edge", { wait: "touch" }, [], ["ask", "greet"], "head_touched"],
    ["'ready' heard: its edge, the end", { wait: "ready" }, [], ["ask"], "heard_ready"],
    ["nothing sensed, the time let run out: the limit's edge", {}, ["wait"], ["ask", "prompt"], undefined],
    ["an event chosen wins over the time running out", { wait: "touch" }, ["wait"], ["ask", "greet"], "head_touched"],
    ["a choice the wait does not offer: the wizard's go on", { wait: "elsewhere" }, [], ["ask", "bye"], undefined],
  ])("a rehearsal at a wait: %s", (_, chosen: Record<string, string>, runOut: string[], path, event) => {
    const { steps, ending } = rehearse(protocol, chosen, new Set(runOut));
    expect(steps.map((s) => s.stepId)).toEqual(path);
    expect(steps[0]!.sensed?.event).toBe(event);
    expect(ending).toBe("completed");
  });
});
