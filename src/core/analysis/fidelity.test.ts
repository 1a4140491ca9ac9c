import { describe, expect, it } from "vitest";
import { simulate, type Command, type TrialProtocol } from "@/core/trial";
import { done, perfect, protocol } from "./test-trial";
import { type ActionOutcome, fidelityReport, outcomeWords } from "./fidelity";

const report = (commands: Command[]) => fidelityReport(protocol, simulate(protocol, commands).log);

describe("the fidelity report", () => {
  it.each<[string, Command[], Partial<ReturnType<typeof report>["totals"]>, number, Record<string, number>]>([
    // The branch not taken (head shake, its end) is not reached, and does not count against fidelity.
    [
      "a perfect run",
      perfect,
      { planned: 9, executed: 7, notReached: 2, skipped: 0, failed: 0, unscripted: 0 },
      100,
      {},
    ],
    [
      "a skipped gesture",
      [{ kind: "start" }, { kind: "skip", actionId: "wave" }, { kind: "next" }, ...done("hello")],
      { executed: 1, skipped: 1 },
      50,
      { skipped: 1 },
    ],
    [
      "a failed action",
      [
        { kind: "start" },
        { kind: "next" },
        { kind: "failed", actionId: "hello", reason: "robot unreachable" },
        ...done("wave"),
      ],
      { executed: 1, failed: 1 },
      50,
      {},
    ],
    [
      "one action not sent and one sent with its outcome unknown: three words apart",
      [
        { kind: "start" },
        { kind: "next" },
        { kind: "not_sent", actionId: "hello", reason: "too old" },
        { kind: "unknown", actionId: "wave", reason: "link lost" },
      ],
      { executed: 0, failed: 0, notSent: 1, unknown: 1 },
      0,
      {},
    ],
    [
      "an outcome unknown that the robot later reported done",
      [
        { kind: "start" },
        { kind: "next" },
        ...done("hello"),
        { kind: "unknown", actionId: "wave", reason: "link lost" },
        { kind: "completed", actionId: "wave" },
      ],
      { executed: 2, unknown: 0 },
      100,
      {},
    ],
    [
      "a timeout",
      [{ kind: "start" }, { kind: "next" }, { kind: "timed_out", actionId: "hello" }, ...done("wave")],
      { executed: 1, timedOut: 1 },
      50,
      {},
    ],
    [
      "parallel actions triggered one by one stay in order",
      [
        { kind: "start" },
        { kind: "trigger", actionId: "wave" },
        ...done("wave"),
        { kind: "trigger", actionId: "hello" },
        ...done("hello"),
      ],
      { executed: 2, outOfOrder: 0 },
      100,
      {},
    ],
    [
      "an answer recorded before the question was asked",
      [
        { kind: "start" },
        { kind: "next" },
        ...done("hello", "wave"),
        { kind: "next" },
        { kind: "answer", actionId: "answer", optionId: "yes" },
      ],
      { executed: 4, outOfOrder: 1 },
      42.9,
      { out_of_order: 1 },
    ],
    [
      "unscripted speech",
      [{ kind: "start" }, { kind: "unscripted", actionId: "u1", actionType: "say", parameters: { text: "Bless you" } }],
      { unscripted: 1, executed: 0 },
      0,
      { unscripted: 1 },
    ],
    [
      "aborted mid-way",
      [{ kind: "start" }, { kind: "next" }, ...done("hello", "wave"), { kind: "abort", reason: "left" }],
      { executed: 2, notReached: 7 },
      100,
      {},
    ],
  ])("%s", (_name, commands, totals, fidelity, deviations) => {
    const r = report(commands);
    expect(r.totals).toMatchObject(totals);
    expect(r.executionFidelity).toBe(fidelity);
    expect(r.deviations).toEqual(deviations);
  });

  it("tells a branch resolved by the answer from a jump by hand", () => {
    expect(report(perfect).branches).toEqual({ byLogic: 1, byHand: 0 });
    const byHand = report([{ kind: "start" }, { kind: "jump", stepId: "wrong" }]);
    expect(byHand.branches).toEqual({ byLogic: 0, byHand: 1 });
    expect(byHand.deviations).toEqual({ manual_jump: 1 });
  });

  it("times steps and actions from the log", () => {
    const r = report(perfect);
    expect(r.steps.map((s) => [s.stepId, s.reached])).toEqual([
      ["intro", true],
      ["ask", true],
      ["right", true],
      ["wrong", false],
    ]);
    expect(r.steps[0]).toMatchObject({ enteredMs: 10, leftMs: 80, durationMs: 70 });
    expect(r.actions.find((a) => a.actionId === "hello")).toMatchObject({
      outcome: "executed",
      requestedMs: 20,
      dispatchLatencyMs: 20,
      durationMs: 30,
    });
    expect(r.completed).toBe(true);
  });

  it.each<[string, Record<string, unknown> | undefined, "robot" | "unconfirmed" | null]>([
    ["a done message from the robot", { confirmation: { by: "done_topic", confirmed: true } }, "robot"],
    ["a service response", { confirmation: { by: "service_response", confirmed: true } }, "robot"],
    ["an estimated duration", { confirmation: { by: "estimated_duration", confirmed: false } }, "unconfirmed"],
    ["only delivered to the bridge", { confirmation: { by: "delivered", confirmed: false } }, "unconfirmed"],
    ["a log that does not say", undefined, null],
  ])("marks a completion confirmed by %s as %s", (_, detail, confirmation) => {
    const commands: Command[] = [
      { kind: "start" },
      { kind: "next" },
      { kind: "dispatched", actionId: "hello" },
      { kind: "completed", actionId: "hello", ...(detail ? { detail } : {}) },
    ];
    expect(report(commands).actions.find((a) => a.actionId === "hello")?.confirmation).toBe(confirmation);
  });
});

describe("the fidelity report of answers that rejoin", () => {
  const say = (id: string) => ({ id, type: "say", parameters: { text: id } });
  const rejoin = { to: "step" as const, stepId: "bye" };
  const quiz: TrialProtocol = {
    steps: [
      {
        id: "ask",
        name: "Question",
        actions: [
          {
            id: "q",
            type: "record_answer",
            parameters: {
              options: [
                { id: "y", label: "Yes" },
                { id: "n", label: "No" },
              ],
            },
          },
          { id: "b", type: "branch", parameters: { targets: { y: "yes", n: "no" } } },
        ],
      },
      { id: "yes", name: "Yes", after: rejoin, actions: [say("glad")] },
      { id: "no", name: "No", after: rejoin, actions: [say("sorry")] },
      { id: "bye", name: "Goodbye", actions: [say("bye")] },
    ],
  };

  it("counts only the path taken: the other answer's step is not reached, and the shared step is", () => {
    const { log } = simulate(quiz, [
      { kind: "start" },
      { kind: "answer", actionId: "q", optionId: "n" },
      { kind: "next" },
      { kind: "completed", actionId: "sorry" },
      { kind: "next" },
      { kind: "next" },
      { kind: "completed", actionId: "bye" },
      { kind: "next" },
    ]);
    const r = fidelityReport(quiz, log);
    expect(r.steps.map((s) => [s.name, s.reached])).toEqual([
      ["Question", true],
      ["Yes", false],
      ["No", true],
      ["Goodbye", true],
    ]);
    expect(r.executionFidelity).toBe(100);
    expect(r.completed).toBe(true);
    expect(r.deviations).toEqual({});
    expect(r.branches).toEqual({ byLogic: 1, byHand: 0 });
  });
});

describe("outcomes in the researcher's words", () => {
  it.each<[ActionOutcome, string]>([
    ["not_sent", "not sent"],
    ["unknown", "sent, outcome unknown"],
    ["failed", "failed"],
    ["timed_out", "timed out"],
    ["not_reached", "not reached"],
  ])("%s: %s", (outcome, words) => {
    expect(outcomeWords(outcome)).toBe(words);
  });
});

describe("the fidelity report of waits for the robot's senses", () => {
  // Two waits: the first ended by a head touch, the second by its time limit; then the wizard's go on ends a third.
  const wait = (id: string, to: string): TrialProtocol["steps"][number]["actions"][number] => ({
    id,
    type: "wait_for",
    parameters: { events: [{ id: "t", event: "head_touched", after: { to: "step", stepId: to } }] },
    timeLimit: { seconds: 5, after: { to: "step", stepId: to } },
  });
  const waits: TrialProtocol = {
    steps: [
      { id: "a", name: "A", actions: [wait("wa", "b")] },
      { id: "b", name: "B", actions: [wait("wb", "c")] },
      { id: "c", name: "C", after: { to: "step", stepId: "d" }, actions: [wait("wc", "a")] },
      { id: "d", name: "D", after: { to: "end" }, actions: [{ id: "bye", type: "say", parameters: { text: "Bye" } }] },
    ],
  };
  const commands: Command[] = [
    { kind: "start" },
    { kind: "sensed", event: "head_touched", at: 1, message: { data: true } },
    { kind: "timer_fired", timerId: "wait:wb:2" },
    { kind: "go_on" },
  ];

  it("counts which moves the robot's senses made, which a timer, which the wizard", () => {
    const r = fidelityReport(waits, simulate(waits, commands).log);
    expect(r.moves).toEqual({
      start: 1,
      next: 0,
      answer: 0,
      jump: 0,
      timer: 1,
      loop: 0,
      bound: 0,
      senses: 1,
      go_on: 1,
    });
    // A wait ended by the senses or the wizard was carried out as designed; one its limit ended, as an unanswered question, not.
    expect(r.actions.map((a) => [a.actionId, a.outcome])).toEqual([
      ["wa", "executed"],
      ["wb", "not_reached"],
      ["wc", "executed"],
      ["bye", "not_reached"],
    ]);
  });
});
