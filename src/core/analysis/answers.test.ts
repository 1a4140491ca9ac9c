import { describe, expect, it } from "vitest";
import { simulate, type Command, type TrialProtocol } from "@/core/trial";
import { answerOf, questionOf, recordedAnswers } from "./answers";
import { fidelityReport } from "./fidelity";
import { done, perfect, protocol } from "./test-trial";

const log = (commands: Command[]) => simulate(protocol, commands).log;
const toQuestion: Command[] = [{ kind: "start" }, { kind: "next" }, ...done("hello", "wave"), { kind: "next" }];
/** The question again: the trial jumps back to it after a first answer. */
const askedTwice: Command[] = [
  ...toQuestion,
  { kind: "next" },
  ...done("q"),
  { kind: "answer", actionId: "answer", optionId: "no" },
  { kind: "jump", stepId: "ask" },
  { kind: "next" },
  ...done("q"),
  { kind: "answer", actionId: "answer", optionId: "yes" },
];

describe("the answers recorded in a trial", () => {
  it.each<[string, Command[], Array<[string, string]>]>([
    ["none before the question", toQuestion, []],
    ["the one answer of a perfect run", perfect, [["Record answer", "red"]]],
    [
      "a question asked again: each answer, in log order",
      askedTwice,
      [
        ["Record answer", "other"],
        ["Record answer", "red"],
      ],
    ],
  ])("%s", (_, commands, expected) => {
    const answers = recordedAnswers(protocol, log(commands));
    expect(answers.map((a) => [a.question, a.answer])).toEqual(expected);
    for (const a of answers) expect(a.options).toEqual(["red", "other"]);
  });

  it("puts the answer beside its question in planned versus executed, the first one given", () => {
    const report = fidelityReport(protocol, log(askedTwice));
    expect(report.actions.filter((a) => a.answer !== null).map((a) => [a.actionId, a.answer])).toEqual([
      ["answer", "other"],
    ]);
    expect(report.answers).toHaveLength(2);
  });
});

describe("a question's name", () => {
  const question = (name: string | undefined, prompt: unknown): TrialProtocol["steps"][number]["actions"][number] => ({
    id: "q",
    type: "record_answer",
    ...(name !== undefined && { name }),
    parameters: { prompt, options: [] },
  });
  it.each<[string, string | undefined, unknown, string]>([
    ["its label first", "Planet", "Which planet is the red one, would you say?", "Planet"],
    [
      "else its whole text for the wizard, never cut",
      undefined,
      "Which planet is the red one, would you say?",
      "Which planet is the red one, would you say?",
    ],
    ["else its block's name", "  ", "", "Record answer"],
  ])("%s", (_, name, prompt, expected) => {
    expect(questionOf(question(name, prompt))).toBe(expected);
  });
});

describe("the answer an event records", () => {
  it.each<[string, object, string | undefined]>([
    ["an answer: its label", { type: "answer.recorded", label: "Mars" }, "Mars"],
    ["a branch that followed it: none", { type: "branch.resolved", optionId: "mars" }, undefined],
    ["a step entered: none", { type: "step.entered", stepId: "s" }, undefined],
  ])("%s", (_, event, expected) => {
    expect(answerOf(event)).toBe(expected);
  });
});
