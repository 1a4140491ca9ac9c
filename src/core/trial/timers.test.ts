import { describe, expect, it } from "vitest";
import {
  decide,
  decideReports,
  fold,
  remainingMs,
  rehearse,
  simulate,
  type Command,
  type EngineEvent,
  type TrialEvent,
  type TrialProtocol,
} from "./index";

// A question with "no answer in 10 s → Prompt", in a step that may last 60 s (→ the next step).
const protocol: TrialProtocol = {
  steps: [
    {
      id: "ask",
      name: "Question",
      timeLimit: { seconds: 60, after: { to: "next" } },
      actions: [
        { id: "say", type: "say", parameters: { text: "What color?" } },
        {
          id: "answer",
          type: "record_answer",
          parameters: { options: [{ id: "red", label: "red" }] },
          timeLimit: { seconds: 10, after: { to: "step", stepId: "prompt" } },
        },
      ],
    },
    { id: "bye", name: "Goodbye", after: { to: "end" }, actions: [] },
    { id: "prompt", name: "Prompt", timeLimit: { seconds: 5, after: { to: "end" } }, actions: [] },
  ],
};

const STEP = "step:ask:1";
const ANSWER = "answer:answer:1";
const asked: Command[] = [
  { kind: "start" },
  { kind: "next" },
  { kind: "dispatched", actionId: "say" },
  { kind: "completed", actionId: "say" },
];

const brief = (events: EngineEvent[] | string) =>
  typeof events === "string"
    ? events
    : events.map((e) =>
        e.type.startsWith("timer.")
          ? [e.type, (e as { timerId: string }).timerId]
          : [e.type, "stepId" in e ? e.stepId : "actionId" in e ? e.actionId : null, e.deviation ?? null],
      );

describe("time limits", () => {
  it.each<[string, Command[], unknown]>([
    [
      "a step's clock starts as it is entered",
      [{ kind: "start" }],
      [
        ["trial.started", null, null],
        ["step.entered", "ask", null],
        ["timer.started", STEP],
      ],
    ],
    [
      "a question's clock waits while the line before it runs",
      [...asked.slice(0, 3)],
      [["action.dispatched", "say", null]],
    ],
    [
      "and starts once the actions before it are done",
      [...asked.slice(0, 3), asked[3]!],
      [
        ["action.completed", "say", null],
        ["timer.started", ANSWER],
      ],
    ],
    [
      "no answer in time: the question's edge, both clocks of the step stopped, the next step's started",
      [...asked, { kind: "timer_fired", timerId: ANSWER }],
      [
        ["timer.fired", ANSWER],
        ["step.entered", "prompt", null],
        ["timer.cancelled", STEP],
        ["timer.started", "step:prompt:2"],
      ],
    ],
    [
      "the step's time running out takes its own way on (the next step)",
      [...asked, { kind: "timer_fired", timerId: STEP }],
      [
        ["timer.fired", STEP],
        ["step.entered", "bye", null],
        ["timer.cancelled", ANSWER],
      ],
    ],
    [
      "a time limit leading to the end ends the trial",
      [...asked, { kind: "timer_fired", timerId: ANSWER }, { kind: "timer_fired", timerId: "step:prompt:2" }],
      [
        ["timer.fired", "step:prompt:2"],
        ["trial.completed", null, null],
      ],
    ],
    [
      "the wizard answering first cancels the question's clock",
      [...asked, { kind: "answer", actionId: "answer", optionId: "red" }],
      [
        ["answer.recorded", "ask", null],
        ["timer.cancelled", ANSWER],
      ],
    ],
    [
      "which then never fires",
      [...asked, { kind: "answer", actionId: "answer", optionId: "red" }, { kind: "timer_fired", timerId: ANSWER }],
      "That timer is no longer running: the wizard acted first, or it fired.",
    ],
    [
      "the wizard leaving the step first cancels its clocks",
      [...asked, { kind: "jump", stepId: "bye" }],
      [
        ["step.entered", "bye", "manual_jump"],
        ["timer.cancelled", STEP],
        ["timer.cancelled", ANSWER],
      ],
    ],
    [
      "a timer fires exactly once",
      [...asked, { kind: "timer_fired", timerId: STEP }, { kind: "timer_fired", timerId: STEP }],
      "That timer is no longer running: the wizard acted first, or it fired.",
    ],
    [
      "a timer does not fire while the trial is paused (it fires once resumed)",
      [...asked, { kind: "pause" }, { kind: "timer_fired", timerId: STEP }],
      "The trial is paused: resume it first.",
    ],
    [
      "ending the trial cancels every clock",
      [...asked, { kind: "abort", reason: "fire alarm" }],
      [
        ["trial.aborted", null, null],
        ["timer.cancelled", STEP],
        ["timer.cancelled", ANSWER],
      ],
    ],
    [
      "a step entered again starts a clock of its own",
      [...asked, { kind: "jump", stepId: "bye" }, { kind: "jump", stepId: "ask" }],
      [
        ["step.entered", "ask", "manual_jump"],
        ["timer.started", "step:ask:3"],
      ],
    ],
  ])("%s", (_, commands, expected) => {
    expect(brief(simulate(protocol, commands).last)).toEqual(expected);
  });

  it("logs a timer that fires as the protocol, never as a deviation", () => {
    const { log } = simulate(protocol, [...asked, { kind: "timer_fired", timerId: ANSWER }]);
    expect(log.filter((e) => e.deviation)).toEqual([]);
    expect(log.find((e) => e.type === "step.entered" && e.stepId === "prompt")).toMatchObject({ via: "timeout" });
  });

  it("keeps each running timer with its start, and none once fired or cancelled", () => {
    const { log } = simulate(protocol, asked, (i) => i * 100);
    expect(fold(protocol, log).timers).toEqual({
      [STEP]: { stepId: "ask", seconds: 60, startedMs: 200, pausedMs: 0 },
      [ANSWER]: { stepId: "ask", actionId: "answer", seconds: 10, startedMs: 600, pausedMs: 0 },
    });
    const fired = simulate(protocol, [...asked, { kind: "timer_fired", timerId: ANSWER }]).log;
    expect(Object.keys(fold(protocol, fired).timers)).toEqual(["step:prompt:2"]);
  });

  it("starts a question's clock from robot reports that came together, once", () => {
    const { log } = simulate(protocol, asked.slice(0, 2));
    const state = fold(protocol, log);
    const events = decideReports(protocol, state, [
      { kind: "dispatched", actionId: "say" },
      { kind: "completed", actionId: "say" },
    ]);
    expect(brief(events)).toEqual([
      ["action.dispatched", "say", null],
      ["action.completed", "say", null],
      ["timer.started", ANSWER],
    ]);
    // The state decided on is left as it was: the live host applies the events once they are logged.
    expect(state.timers).toEqual({ [STEP]: expect.anything() });
    expect(decide(protocol, state, { kind: "timer_fired", timerId: ANSWER }).ok).toBe(false);
  });
});

// The step's 60 s limit, started at t0; then pauses and resumes at the given ms from t0.
const opened: EngineEvent[] = [
  { type: "trial.started" },
  { type: "step.entered", stepId: "ask", via: "start" },
  { type: "timer.started", timerId: STEP, stepId: "ask", seconds: 60 },
];
const at = (relMs: number, event: EngineEvent): [number, EngineEvent] => [relMs, event];
const pause = (relMs: number) => at(relMs, { type: "trial.paused" });
const resume = (relMs: number) => at(relMs, { type: "trial.resumed" });
const logOf = (later: [number, EngineEvent][]): TrialEvent[] =>
  [...opened.map((e) => at(0, e)), ...later].map(([relMs, e], i) => ({ ...e, seq: i + 1, relMs }));

describe("a paused trial's time limits", () => {
  it.each<[string, [number, EngineEvent][], number, number]>([
    ["running: its limit less the time since it started", [], 20_000, 40_000],
    ["past due while running: nothing left", [], 70_000, 0],
    ["paused before due: the clock holds what it had left", [pause(20_000)], 50_000, 40_000],
    ["paused across due: it still has what it had left", [pause(50_000)], 90_000, 10_000],
    ["resumed after the pause: the time paused is not counted", [pause(50_000), resume(80_000)], 85_000, 5_000],
    [
      "paused twice: neither pause counted",
      [pause(10_000), resume(20_000), pause(30_000), resume(45_000)],
      50_000,
      35_000,
    ],
    ["an emergency stop stops the clocks too", [at(5_000, { type: "trial.emergency_stop" })], 30_000, 55_000],
    [
      "a stop during a pause: the clocks stood still from the pause",
      [pause(5_000), at(8_000, { type: "trial.emergency_stop" }), resume(20_000)],
      20_000,
      55_000,
    ],
  ])("%s", (_, later, nowMs, left) => {
    const state = fold(protocol, logOf(later));
    expect(remainingMs(state.timers[STEP]!, state, nowMs)).toBe(left);
  });

  it("starts the clock of a timer started during a pause at the resume", () => {
    const started: [number, EngineEvent] = at(15_000, {
      type: "timer.started",
      timerId: ANSWER,
      stepId: "ask",
      actionId: "answer",
      seconds: 10,
    });
    const paused = fold(protocol, logOf([pause(10_000), started]));
    expect(remainingMs(paused.timers[ANSWER]!, paused, 60_000)).toBe(10_000);
    const resumed = fold(protocol, logOf([pause(10_000), started, resume(40_000)]));
    expect(remainingMs(resumed.timers[ANSWER]!, resumed, 45_000)).toBe(5_000);
    expect(remainingMs(resumed.timers[STEP]!, resumed, 45_000)).toBe(45_000);
  });
});

describe("rehearsing a time limit's edge", () => {
  it.each<[string, string[], Array<[string, { seconds: number; question: boolean } | undefined]>]>([
    [
      "answered in time: the way the answer leads",
      [],
      [
        ["ask", undefined],
        ["bye", undefined],
      ],
    ],
    [
      "no answer in time: the question's edge",
      ["answer"],
      [
        ["ask", { seconds: 10, question: true }],
        ["prompt", undefined],
      ],
    ],
    [
      "the step's time running out once its actions are done: the step's edge",
      ["ask"],
      [
        ["ask", { seconds: 60, question: false }],
        ["bye", undefined],
      ],
    ],
    [
      "one edge after another, to a limit that ends the trial",
      ["answer", "prompt"],
      [
        ["ask", { seconds: 10, question: true }],
        ["prompt", { seconds: 5, question: false }],
      ],
    ],
    [
      "a step without a time limit waits for the wizard as ever",
      ["bye"],
      [
        ["ask", undefined],
        ["bye", undefined],
      ],
    ],
  ])("%s", (_, runOut, path) => {
    const rehearsal = rehearse(protocol, {}, new Set(runOut));
    expect(rehearsal.steps.map((step) => [step.stepId, step.timeout])).toEqual(path);
    expect(rehearsal.ending).toBe("completed");
  });
});
