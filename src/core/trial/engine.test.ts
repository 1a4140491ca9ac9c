import { describe, expect, it } from "vitest";
import {
  apply,
  applyAll,
  applyInPlace,
  decideAfterReports,
  decideReports,
  fold,
  simulate,
  type Command,
  type EngineEvent,
  type RobotReportCommand,
  type TrialProtocol,
} from "./index";

// A small Storyteller: speech and wave together, a pause, a question, a branch.
const protocol: TrialProtocol = {
  steps: [
    {
      id: "intro",
      name: "Introduction",
      actions: [
        { id: "hello", type: "say", parameters: { text: "Hello." }, parallelGroup: "g1" },
        { id: "wave", type: "wave", parameters: {}, parallelGroup: "g1" },
        { id: "note", type: "wizard_instruction", parameters: { text: "Smile" } },
      ],
    },
    {
      id: "recall",
      name: "Recall question",
      actions: [
        { id: "hold", type: "pause", parameters: { seconds: 2 } },
        { id: "ask", type: "say", parameters: { text: "What color?" } },
        {
          id: "answer",
          type: "record_answer",
          parameters: {
            options: [
              { id: "correct", label: "red" },
              { id: "incorrect", label: "other" },
            ],
          },
        },
        { id: "branch", type: "branch", parameters: { targets: { correct: "yes", incorrect: "no" } } },
      ],
    },
    {
      id: "yes",
      name: "Correct",
      actions: [
        { id: "nod", type: "nod", parameters: {} },
        { id: "end-yes", type: "end_trial", parameters: {} },
      ],
    },
    {
      id: "no",
      name: "Incorrect",
      actions: [
        { id: "shake", type: "head_shake", parameters: {} },
        { id: "end-no", type: "end_trial", parameters: {} },
      ],
    },
  ],
};

/** Runs commands in order; returns the events of the last one (or its rejection), the log and the state. */
function run(commands: Command[]) {
  const { log, last } = simulate(protocol, commands);
  return { last, log, state: fold(protocol, log) };
}

const start: Command[] = [{ kind: "start" }];
const introDone: Command[] = [
  ...start,
  { kind: "next" },
  { kind: "dispatched", actionId: "hello" },
  { kind: "completed", actionId: "hello" },
  { kind: "dispatched", actionId: "wave" },
  { kind: "completed", actionId: "wave" },
  { kind: "next" },
];
const atQuestion: Command[] = [
  ...introDone,
  { kind: "next" },
  { kind: "next" },
  { kind: "dispatched", actionId: "hold" },
  { kind: "completed", actionId: "hold" },
  { kind: "next" },
];

const brief = (events: EngineEvent[] | string) =>
  typeof events === "string"
    ? events
    : events.map((e) => [e.type, "actionId" in e ? e.actionId : "stepId" in e ? e.stepId : null, e.deviation ?? null]);

describe("the trial engine", () => {
  it.each<[string, Command[], unknown]>([
    [
      "start enters the first step",
      start,
      [
        ["trial.started", null, null],
        ["step.entered", "intro", null],
      ],
    ],
    [
      "a recording's start is logged before the trial starts",
      [{ kind: "recording", recordingId: "r1", offsetMs: -1500 }],
      [["recording.started", null, null]],
    ],
    [
      "and while it runs, changing nothing else",
      [...start, { kind: "recording", recordingId: "r1", offsetMs: 800 }],
      [["recording.started", null, null]],
    ],
    [
      "a problem the robot's side reported is logged before the trial starts",
      [{ kind: "robot_problem", text: "subscribe: Unable to load the manifest for package no_such_msgs" }],
      [["robot.problem", null, null]],
    ],
    [
      "and while it runs or is paused",
      [...start, { kind: "pause" }, { kind: "robot_problem", text: "the robot's bridge reported a warning: x" }],
      [["robot.problem", null, null]],
    ],
    [
      "but not once the trial has ended",
      [...start, { kind: "abort", reason: "stopped" }, { kind: "robot_problem", text: "late" }],
      "This trial has already ended.",
    ],
    ["nor without words", [{ kind: "robot_problem", text: " " }], "The robot's problem has no text."],
    [
      "next starts a parallel group together",
      [...start, { kind: "next" }],
      [
        ["action.requested", "hello", null],
        ["action.requested", "wave", null],
      ],
    ],
    [
      "a wizard instruction finishes as it starts",
      [...introDone],
      [
        ["action.requested", "note", null],
        ["action.completed", "note", null],
      ],
    ],
    [
      "next on a finished step enters the following one",
      [...introDone, { kind: "next" }],
      [["step.entered", "recall", null]],
    ],
    [
      "a pause is requested; the clock completes it",
      [...introDone, { kind: "next" }, { kind: "next" }],
      [["action.requested", "hold", null]],
    ],
    [
      "next waits while a designed pause runs",
      [...introDone, { kind: "next" }, { kind: "next" }, { kind: "next" }],
      "Wait: the 2 s pause is still running.",
    ],
    [
      "the question must be answered, not skipped past by next",
      [...atQuestion, { kind: "next" }],
      "Record the participant's answer: red or other.",
    ],
    [
      "an answer resolves the branch to its step by itself",
      [...atQuestion, { kind: "answer", actionId: "answer", optionId: "incorrect" }],
      [
        ["answer.recorded", "answer", null],
        ["branch.resolved", "branch", null],
        ["step.entered", "no", null],
      ],
    ],
    [
      "an unknown answer is refused",
      [...atQuestion, { kind: "answer", actionId: "answer", optionId: "blue" }],
      '"blue" is not one of this question\'s answers.',
    ],
    ["skip marks a deviation", [...start, { kind: "skip", actionId: "wave" }], [["action.skipped", "wave", "skipped"]]],
    [
      "skip with no action skips the whole next unit",
      [...start, { kind: "skip" }],
      [
        ["action.skipped", "hello", "skipped"],
        ["action.skipped", "wave", "skipped"],
      ],
    ],
    [
      "triggering a later action is out of order",
      [...start, { kind: "trigger", actionId: "note" }],
      [
        ["action.requested", "note", "out_of_order"],
        ["action.completed", "note", null],
      ],
    ],
    [
      "triggering the next action is in order",
      [...start, { kind: "trigger", actionId: "wave" }],
      [["action.requested", "wave", null]],
    ],
    [
      "an action of another step needs a jump first",
      [...start, { kind: "trigger", actionId: "nod" }],
      '"Nod" belongs to another step: jump to "Correct" first.',
    ],
    [
      "a manual jump is a deviation",
      [...start, { kind: "jump", stepId: "yes" }],
      [["step.entered", "yes", "manual_jump"]],
    ],
    [
      "an unscripted action is a deviation",
      [...start, { kind: "unscripted", actionId: "u1", actionType: "say", parameters: { text: "Bless you" } }],
      [["action.requested", "u1", "unscripted"]],
    ],
    [
      "end_trial completes the trial",
      [...atQuestion, { kind: "answer", actionId: "answer", optionId: "correct" }, { kind: "next" }, { kind: "next" }],
      [
        ["action.requested", "end-yes", null],
        ["action.completed", "end-yes", null],
        ["trial.completed", null, null],
      ],
    ],
    ["completing early is a deviation", [...start, { kind: "complete" }], [["trial.completed", null, "ended_early"]]],
    [
      "a paused trial refuses next",
      [...start, { kind: "pause" }, { kind: "next" }],
      "The trial is paused: resume it first.",
    ],
    [
      "resume continues a paused trial",
      [...start, { kind: "pause" }, { kind: "resume" }, { kind: "next" }],
      [
        ["action.requested", "hello", null],
        ["action.requested", "wave", null],
      ],
    ],
    ["emergency stop pauses the trial", [...start, { kind: "emergency_stop" }], [["trial.emergency_stop", null, null]]],
    [
      "abort ends the trial",
      [...start, { kind: "abort", reason: "participant left" }],
      [["trial.aborted", null, null]],
    ],
    [
      "nothing runs after an abort",
      [...start, { kind: "abort", reason: "x" }, { kind: "next" }],
      "The trial is not running.",
    ],
    ["a second start is refused", [...start, { kind: "start" }], "This trial has already started."],
    [
      "a failure is recorded with its reason",
      [...start, { kind: "next" }, { kind: "failed", actionId: "hello", reason: "robot unreachable" }],
      [["action.failed", "hello", null]],
    ],
    [
      "a timeout is recorded",
      [...start, { kind: "next" }, { kind: "dispatched", actionId: "hello" }, { kind: "timed_out", actionId: "hello" }],
      [["action.timed_out", "hello", null]],
    ],
    [
      "a late completion after a timeout is refused",
      [...start, { kind: "next" }, { kind: "timed_out", actionId: "hello" }, { kind: "completed", actionId: "hello" }],
      "The robot reported on an action that has already finished.",
    ],
    [
      "a report on an action never requested is refused",
      [...start, { kind: "completed", actionId: "hello" }],
      "The robot reported on an action that was never requested.",
    ],
  ])("%s", (_name, commands, expected) => {
    expect(brief(run(commands).last)).toEqual(expected);
  });

  it("resumes from its events: the fold of a log equals the state that produced it", () => {
    const { log, state } = run([...atQuestion, { kind: "answer", actionId: "answer", optionId: "correct" }]);
    // A runtime that crashed after event 5 folds those, then applies the rest as they come.
    const resumed = log.slice(5).reduce(apply, fold(protocol, log.slice(0, 5)));
    expect(resumed).toEqual(state);
    expect(state.currentStepId).toBe("yes");
    expect(state.answers).toEqual({ answer: "correct" });
    expect(state.actions.hold!.status).toBe("done");
  });

  it("times every action from its events", () => {
    const { state } = run([
      ...start,
      { kind: "next" },
      { kind: "dispatched", actionId: "hello" },
      { kind: "completed", actionId: "hello" },
    ]);
    expect(state.actions.hello).toEqual({ status: "done", requestedAt: 20, finishedAt: 50 });
  });
});

describe("robot reports that came together", () => {
  // Both lines of the introduction requested, neither dispatched yet.
  const requested = [...start, { kind: "next" } as const];
  it.each<[string, RobotReportCommand[], unknown]>([
    [
      "a dispatch and its completion, decided one after the other",
      [
        { kind: "dispatched", actionId: "hello" },
        { kind: "completed", actionId: "hello" },
      ],
      [
        ["action.dispatched", "hello", null],
        ["action.completed", "hello", null],
      ],
    ],
    [
      "two actions' outcomes, interleaved as they came",
      [
        { kind: "dispatched", actionId: "hello" },
        { kind: "dispatched", actionId: "wave" },
        { kind: "failed", actionId: "wave", reason: "no arms" },
        { kind: "completed", actionId: "hello" },
      ],
      [
        ["action.dispatched", "hello", null],
        ["action.dispatched", "wave", null],
        ["action.failed", "wave", null],
        ["action.completed", "hello", null],
      ],
    ],
    [
      "a report after its action finished in the same batch is left out, as it would be alone",
      [
        { kind: "timed_out", actionId: "hello" },
        { kind: "completed", actionId: "hello" },
      ],
      [["action.timed_out", "hello", null]],
    ],
    [
      "a second dispatch is left out",
      [
        { kind: "dispatched", actionId: "hello" },
        { kind: "dispatched", actionId: "hello" },
      ],
      [["action.dispatched", "hello", null]],
    ],
    ["a report on an action never requested is left out", [{ kind: "completed", actionId: "nod" }], []],
    [
      "sent, outcome unknown, then the robot's own completion: logged against it",
      [
        { kind: "dispatched", actionId: "hello" },
        { kind: "unknown", actionId: "hello", reason: "the link was lost" },
        { kind: "completed", actionId: "hello" },
      ],
      [
        ["action.dispatched", "hello", null],
        ["action.unknown", "hello", null],
        ["action.completed", "hello", null],
      ],
    ],
    [
      "not sent is final: a later report is left out",
      [
        { kind: "not_sent", actionId: "hello", reason: "too old" },
        { kind: "completed", actionId: "hello" },
      ],
      [["action.not_sent", "hello", null]],
    ],
  ])("%s", (_name, reports, expected) => {
    const { state, log } = run(requested);
    expect(brief(decideReports(protocol, state, reports))).toEqual(expected);
    // The same events as each report decided alone, in turn, after the others were logged.
    const oneByOne = simulate(protocol, [...requested, ...reports]).log.slice(log.length);
    expect(decideReports(protocol, state, reports)).toEqual(oneByOne.map(({ seq: _, relMs: __, ...event }) => event));
  });

  it("leaves the state it was given as it was", () => {
    const { state } = run(requested);
    const before = structuredClone(state);
    decideReports(protocol, state, [
      { kind: "dispatched", actionId: "hello" },
      { kind: "completed", actionId: "hello" },
    ]);
    expect(state).toEqual(before);
  });
});

describe("a command with the robot's reports that wait for their append", () => {
  // Each case: the log so far, the reports waiting, the command.
  it.each<[string, Command[], RobotReportCommand[], Command, unknown]>([
    [
      "the pause reported over lets the wizard go on, in the same append",
      [...introDone, { kind: "next" }, { kind: "next" }],
      [
        { kind: "dispatched", actionId: "hold" },
        { kind: "completed", actionId: "hold" },
      ],
      { kind: "next" },
      [
        ["action.dispatched", "hold", null],
        ["action.completed", "hold", null],
        ["action.requested", "ask", null],
      ],
    ],
    [
      "the last line's outcomes, then the wizard's next line",
      [...start, { kind: "next" }],
      [
        { kind: "dispatched", actionId: "hello" },
        { kind: "completed", actionId: "hello" },
      ],
      { kind: "unscripted", actionId: "ad-lib", actionType: "say", parameters: { text: "Hm." } },
      [
        ["action.dispatched", "hello", null],
        ["action.completed", "hello", null],
        ["action.requested", "ad-lib", "unscripted"],
      ],
    ],
    [
      "a report on an action already finished is left out, the command goes on",
      [...introDone],
      [{ kind: "completed", actionId: "hello" }],
      { kind: "note", text: "fine" },
      [["note.added", null, null]],
    ],
    [
      "no reports: the command alone",
      [...start],
      [],
      { kind: "next" },
      [
        ["action.requested", "hello", null],
        ["action.requested", "wave", null],
      ],
    ],
  ])("%s", (_name, before, reports, command, expected) => {
    const { state, log } = run(before);
    const { reports: logged, decision } = decideAfterReports(protocol, state, reports, command);
    expect(decision.ok).toBe(true);
    const events = [...logged, ...(decision.ok ? decision.events : [])];
    expect(brief(events)).toEqual(expected);
    // The same events as the reports logged first, each in turn, then the command decided after them.
    const inTurn = simulate(protocol, [...before, ...reports, command]).log.slice(log.length);
    expect(events).toEqual(inTurn.map(({ seq: _, relMs: __, ...event }) => event));
  });

  it("keeps the reports' events when the command is refused, refused as it would be after them", () => {
    const { state } = run([...start, { kind: "next" }]);
    const { reports, decision } = decideAfterReports(protocol, state, [{ kind: "dispatched", actionId: "hello" }], {
      kind: "jump",
      stepId: "intro",
    });
    expect(brief(reports)).toEqual([["action.dispatched", "hello", null]]);
    expect(decision).toEqual({ ok: false, reason: "The trial is already at that step." });
  });

  it("refuses what only the reports allow when they are not there: the pause still running", () => {
    const { state } = run([...introDone, { kind: "next" }, { kind: "next" }]);
    expect(decideAfterReports(protocol, state, [], { kind: "next" }).decision).toEqual({
      ok: false,
      reason: "Wait: the 2 s pause is still running.",
    });
  });

  it("leaves the state it was given as it was", () => {
    const { state } = run([...introDone, { kind: "next" }, { kind: "next" }]);
    const before = structuredClone(state);
    decideAfterReports(
      protocol,
      state,
      [
        { kind: "dispatched", actionId: "hold" },
        { kind: "completed", actionId: "hold" },
      ],
      { kind: "next" },
    );
    expect(state).toEqual(before);
  });
});

describe("applying events in batches", () => {
  // A full trial with an unscripted line, a pause and a loop-free branch: every kind of event the fold reads.
  const { log } = simulate(protocol, [
    ...atQuestion,
    { kind: "unscripted", actionId: "ad-lib", actionType: "say", parameters: { text: "Hm." } },
    { kind: "dispatched", actionId: "ad-lib" },
    { kind: "completed", actionId: "ad-lib" },
    { kind: "pause" },
    { kind: "resume" },
    { kind: "answer", actionId: "answer", optionId: "correct" },
    { kind: "next" },
  ]);

  it("covers the whole trial (the commands above were all accepted)", () => {
    const state = fold(protocol, log);
    expect(state.answers).toEqual({ answer: "correct" });
    expect(state.actions["ad-lib"]?.status).toBe("done");
    expect(state.path).toEqual(["intro", "recall", "yes"]);
  });

  it.each([1, 2, 3, 5, log.length])("gives the state of one fold whatever the batch size (%i)", (size) => {
    let state = fold(protocol, []);
    for (let i = 0; i < log.length; i += size) state = applyAll(state, log.slice(i, i + size));
    expect(state).toEqual(fold(protocol, log));
  });

  it.each([1, 3, log.length])(
    "moves the runtime's own state in place to the state of one fold (batches of %i)",
    (size) => {
      const state = fold(protocol, []);
      for (let i = 0; i < log.length; i += size) applyInPlace(state, log.slice(i, i + size));
      expect(state).toEqual(fold(protocol, log));
    },
  );

  it("leaves the state it started from as it was, so the page's earlier renders stay true", () => {
    const half = fold(protocol, log.slice(0, 4));
    const before = structuredClone(half);
    applyAll(half, log.slice(4));
    apply(half, log[4]!);
    expect(half).toEqual(before);
  });
});
