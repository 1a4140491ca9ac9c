import { describe, expect, it } from "vitest";
import type { After } from "../protocol/document";
import { fold, rehearse, simulate, type Command, type TrialProtocol } from "./index";

const say = (id: string) => ({ id, type: "say", parameters: { text: id } });

// The newcomer's quiz: a question with three answers, one step per answer, all rejoining Goodbye.
function quiz(afters: Partial<Record<string, After>> = {}): TrialProtocol {
  const goodbye: After = { to: "step", stepId: "goodbye" };
  return {
    steps: [
      {
        id: "ask",
        name: "Question",
        actions: [
          say("which-planet"),
          {
            id: "answer",
            type: "record_answer",
            parameters: {
              options: [
                { id: "mars", label: "Mars" },
                { id: "venus", label: "Venus" },
                { id: "silent", label: "No answer" },
              ],
            },
          },
          {
            id: "branch",
            type: "branch",
            parameters: { targets: { mars: "correct", venus: "wrong", silent: "silent" } },
          },
        ],
      },
      { id: "correct", name: "Correct", after: afters.correct ?? goodbye, actions: [say("well-done")] },
      { id: "wrong", name: "Wrong", after: afters.wrong ?? goodbye, actions: [say("not-quite")] },
      { id: "silent", name: "Silent", after: afters.silent ?? goodbye, actions: [say("take-your-time")] },
      { id: "goodbye", name: "Goodbye", after: afters.goodbye, actions: [say("bye")] },
    ],
  };
}

/** The wizard's commands through the question to the end of Venus's step, the robot finishing each action. */
const answeredVenus: Command[] = [
  { kind: "start" },
  { kind: "next" },
  { kind: "completed", actionId: "which-planet" },
  { kind: "answer", actionId: "answer", optionId: "venus" },
  { kind: "next" },
  { kind: "completed", actionId: "not-quite" },
  { kind: "next" },
];

const said = (protocol: TrialProtocol, answer: string) =>
  rehearse(protocol, { answer })
    .steps.flatMap((s) => s.units.flat())
    .map((a) => a.id);

describe("where a step leads after its actions", () => {
  it.each([
    ["mars", ["which-planet", "well-done", "bye"]],
    ["venus", ["which-planet", "not-quite", "bye"]],
    ["silent", ["which-planet", "take-your-time", "bye"]],
  ])("answers rejoin a shared step: %s says only its own response", (answer, expected) => {
    expect(said(quiz(), answer)).toEqual(expected);
  });

  it("left to go on to the next, an answer's step falls through into its siblings (what the designer warns about)", () => {
    const next: After = { to: "next" };
    expect(said(quiz({ correct: next, wrong: next, silent: next }), "mars")).toEqual([
      "which-planet",
      "well-done",
      "not-quite",
      "take-your-time",
      "bye",
    ]);
  });

  it("ends the trial where a step says so, marking no early end", () => {
    const protocol = quiz({ wrong: { to: "end" } });
    expect(said(protocol, "venus")).toEqual(["which-planet", "not-quite"]);
    const { log } = simulate(protocol, answeredVenus);
    expect(log.at(-1)).toMatchObject({ type: "trial.completed" });
    expect(log.at(-1)).not.toHaveProperty("deviation");
  });

  it("completing by hand before a step that leads to the end is an early end", () => {
    const { log } = simulate(quiz(), [{ kind: "start" }, { kind: "complete" }]);
    expect(log.at(-1)).toMatchObject({ type: "trial.completed", deviation: "ended_early" });
  });

  it("a loop back runs the revisited step's actions again, and the path records both visits", () => {
    // Wrong asks again; Correct goes on.
    const protocol = quiz({ wrong: { to: "step", stepId: "ask" } });
    const commands: Command[] = [
      ...answeredVenus,
      { kind: "next" },
      { kind: "completed", actionId: "which-planet" },
      { kind: "answer", actionId: "answer", optionId: "mars" },
    ];
    const { log, last } = simulate(protocol, commands);
    expect(last).not.toBeTypeOf("string");
    expect(fold(protocol, log).path).toEqual(["ask", "wrong", "ask", "correct"]);
    expect(log.filter((e) => e.type === "action.requested" && e.actionId === "which-planet")).toHaveLength(2);
  });

  it("a rehearsal whose answers never leave a loop says so instead of running forever", () => {
    const protocol = quiz({ wrong: { to: "step", stepId: "ask" } });
    expect(rehearse(protocol, { answer: "venus" }).ending).toBe("looping");
    expect(rehearse(protocol, { answer: "mars" }).ending).toBe("completed");
  });

  it("a rehearsal names the answer it took at each question", () => {
    const steps = rehearse(quiz(), { answer: "silent" }).steps;
    expect(steps.map((s) => s.name)).toEqual(["Question", "Silent", "Goodbye"]);
    expect(steps[0]!.answer).toEqual({ actionId: "answer", optionId: "silent", label: "No answer" });
  });

  // The designer and the wizard's page number a step by its place in the protocol; the rehearsal must agree.
  it.each([
    ["mars", [1, 2, 5]],
    ["venus", [1, 3, 5]],
    ["silent", [1, 4, 5]],
  ])("a rehearsal numbers each step by its place in the protocol, not its visit order: %s", (answer, numbers) => {
    expect(rehearse(quiz(), { answer }).steps.map((s) => s.number)).toEqual(numbers);
  });
});
