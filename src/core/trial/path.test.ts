import { describe, expect, it } from "vitest";
import { fold, simulate, type Command, type TrialProtocol } from "./index";
import { pathTaken, upcoming } from "./path";

const protocol: TrialProtocol = {
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
    {
      id: "yes",
      name: "Yes",
      after: { to: "step", stepId: "bye" },
      actions: [{ id: "s1", type: "say", parameters: {} }],
    },
    { id: "no", name: "No", after: { to: "end" }, actions: [{ id: "s2", type: "say", parameters: {} }] },
    { id: "bye", name: "Goodbye", actions: [{ id: "s3", type: "say", parameters: {} }] },
  ],
};

const after = (commands: Command[]) => {
  const state = fold(protocol, simulate(protocol, commands).log);
  const next = upcoming(protocol, state);
  return {
    path: pathTaken(protocol, state).map((s) => s.name),
    next:
      next.kind === "step"
        ? next.step.name
        : next.kind === "answer"
          ? next.routes.map((r) => `${r.label}→${r.step?.name}`).join(", ")
          : "end",
  };
};

describe("the wizard's way through", () => {
  it.each<[string, Command[], { path: string[]; next: string }]>([
    ["before the start", [], { path: [], next: "Question" }],
    ["at the question: the answers decide", [{ kind: "start" }], { path: ["Question"], next: "Yes→Yes, No→No" }],
    [
      "after Yes: the rejoin",
      [{ kind: "start" }, { kind: "answer", actionId: "q", optionId: "y" }],
      { path: ["Question", "Yes"], next: "Goodbye" },
    ],
    [
      "after No: the end",
      [{ kind: "start" }, { kind: "answer", actionId: "q", optionId: "n" }],
      { path: ["Question", "No"], next: "end" },
    ],
    [
      "once aborted, nothing comes next",
      [{ kind: "start" }, { kind: "abort", reason: "test" }],
      { path: ["Question"], next: "end" },
    ],
  ])("%s", (_name, commands, expected) => {
    expect(after(commands)).toEqual(expected);
  });
});
