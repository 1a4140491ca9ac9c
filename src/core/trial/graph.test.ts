import { describe, expect, it } from "vitest";
import { flowEdges } from "./graph";
import type { TrialProtocol } from "./types";

const step = (
  id: string,
  actions: TrialProtocol["steps"][number]["actions"] = [],
  after?: TrialProtocol["steps"][number]["after"],
) => ({
  id,
  name: id,
  actions,
  ...(after ? { after } : {}),
});
const question = {
  id: "q",
  type: "record_answer",
  parameters: {
    options: [
      { id: "y", label: "Yes" },
      { id: "n", label: "No" },
    ],
  },
};
const branch = (targets: Record<string, string>) => ({ id: "b", type: "branch", parameters: { targets } });
const brief = (p: TrialProtocol) => flowEdges(p).map((e) => `${e.from}→${e.to}${e.label ? ` ${e.label}` : ""}`);

describe("the flow map's edges", () => {
  it.each<[string, TrialProtocol, string[]]>([
    ["a straight protocol", { steps: [step("a"), step("b")] }, ["0→1", "1→end"]],
    [
      "a wait's events, each to its way on, beside the step's own (the wizard's go on)",
      {
        steps: [
          step("wait", [
            {
              id: "w",
              type: "wait_for",
              parameters: {
                events: [
                  { id: "t", event: "head_touched", after: { to: "step", stepId: "greet" } },
                  { id: "r", event: "heard_ready", after: { to: "end" } },
                ],
              },
            },
          ]),
          step("bye"),
          step("greet"),
        ],
      },
      ["0→1", "0→2 head_touched", "0→end heard_ready", "1→2", "2→end"],
    ],
    [
      "time limits: a step's, and a question's beside its answers",
      {
        steps: [
          {
            ...step("ask", [{ ...question, timeLimit: { seconds: 10, after: { to: "step", stepId: "bye" } } }]),
            timeLimit: { seconds: 60, after: { to: "end" } },
          },
          step("other"),
          step("bye"),
        ],
      },
      ["0→1", "0→end 60 s", "0→2 10 s", "1→2", "2→end"],
    ],
    [
      "answers that rejoin",
      {
        steps: [
          step("ask", [question, branch({ y: "yes", n: "no" })]),
          step("yes", [], { to: "step", stepId: "bye" }),
          step("no", [], { to: "step", stepId: "bye" }),
          step("bye"),
        ],
      },
      ["0→1 Yes", "0→2 No", "1→3", "2→3", "3→end"],
    ],
    [
      "an answer left unrouted keeps the step's own way on",
      { steps: [step("ask", [question, branch({ y: "yes" })]), step("yes")] },
      ["0→1 Yes", "0→1", "1→end"],
    ],
    [
      "End trial ends, whatever the step's after says",
      { steps: [step("a", [{ id: "e", type: "end_trial", parameters: {} }], { to: "step", stepId: "b" }), step("b")] },
      ["0→end", "1→end"],
    ],
    ["an after that ends the trial early", { steps: [step("a", [], { to: "end" }), step("b")] }, ["0→end", "1→end"]],
    [
      "a loop: back with its bound, and on after its last time",
      { steps: [step("a"), step("b", [], { to: "again", stepId: "a", times: 2, onward: { to: "end" } }), step("c")] },
      ["0→1", "1→0 back, at most 2 times", "1→end after 2 times", "2→end"],
    ],
    [
      "a time limit whose way on is a loop",
      {
        steps: [
          {
            ...step("ask"),
            timeLimit: { seconds: 10, after: { to: "again", stepId: "ask", times: 1, onward: { to: "next" } } },
          },
          step("bye"),
        ],
      },
      ["0→1", "0→0 10 s, back, at most once", "0→1 10 s, after once", "1→end"],
    ],
  ])("%s", (_name, protocol, expected) => {
    expect(brief(protocol)).toEqual(expected);
  });
});
