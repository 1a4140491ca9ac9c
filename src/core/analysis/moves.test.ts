import { describe, expect, it } from "vitest";
import { simulate, type Command } from "@/core/trial";
import { moveWords, stepVisits, type Move } from "./moves";
import { done, perfect, protocol } from "./test-trial";

const visits = (commands: Command[]) =>
  stepVisits(simulate(protocol, commands).log).map((v) => [v.stepId, moveWords(v.move), v.skipped]);

describe("what moved the trial at each step", () => {
  it.each<[string, Command[], Array<[string, string, number]>]>([
    ["not started: no step", [], []],
    [
      "a perfect run: the start, the wizard's next, then the answer",
      perfect,
      [
        ["intro", "the start", 0],
        ["ask", "the wizard's next", 0],
        ["right", "the answer “red”", 0],
      ],
    ],
    [
      "the other answer takes the other branch",
      [
        { kind: "start" },
        { kind: "next" },
        ...done("hello", "wave"),
        { kind: "next" },
        { kind: "next" },
        ...done("q"),
        { kind: "answer", actionId: "answer", optionId: "no" },
      ],
      [
        ["intro", "the start", 0],
        ["ask", "the wizard's next", 0],
        ["wrong", "the answer “other”", 0],
      ],
    ],
    [
      "skipped actions count in the step they were skipped in; the next after them is still the wizard's",
      [{ kind: "start" }, { kind: "skip", actionId: "wave" }, { kind: "skip", actionId: "hello" }, { kind: "next" }],
      [
        ["intro", "the start", 2],
        ["ask", "the wizard's next", 0],
      ],
    ],
    [
      "a jump is the wizard's, and a deviation; a step entered again is a visit again",
      [{ kind: "start" }, { kind: "jump", stepId: "wrong" }, { kind: "jump", stepId: "intro" }],
      [
        ["intro", "the start", 0],
        ["wrong", "the wizard's jump (a deviation)", 0],
        ["intro", "the wizard's jump (a deviation)", 0],
      ],
    ],
  ])("%s", (_, commands, expected) => {
    expect(visits(commands)).toEqual(expected);
  });

  it("keeps when each step was entered", () => {
    const log = simulate(protocol, perfect, (i) => i * 100).log;
    const entered = log.filter((e) => e.type === "step.entered").map((e) => e.relMs);
    expect(stepVisits(log).map((v) => v.enteredMs)).toEqual(entered);
  });

  it.each<[Move, string]>([
    [{ by: "start" }, "the start"],
    [{ by: "next" }, "the wizard's next"],
    [{ by: "answer", answer: "Mars" }, "the answer “Mars”"],
    [{ by: "jump" }, "the wizard's jump (a deviation)"],
    [{ by: "loop", round: 2 }, "the loop going back (time 2)"],
    [{ by: "bound", times: 1 }, "a loop's bound (once) reached"],
  ])("says %j as %s", (move, words) => {
    expect(moveWords(move)).toBe(words);
  });
});

describe("what ended a wait", () => {
  const waitProtocol = {
    steps: [
      {
        id: "wait-step",
        name: "Wait",
        actions: [
          {
            id: "wait",
            type: "wait_for",
            parameters: { events: [{ id: "touch", event: "head_touched", after: { to: "step", stepId: "greet" } }] },
          },
        ],
      },
      { id: "bye", name: "Goodbye", after: { to: "end" as const }, actions: [] },
      { id: "greet", name: "Greet", after: { to: "end" as const }, actions: [] },
    ],
  };
  it.each<[string, Command, [string, string]]>([
    [
      "the robot's senses, naming the event",
      { kind: "sensed", event: "head_touched", at: 1, message: null },
      ["greet", "the robot's senses (“head_touched”)"],
    ],
    ["the wizard's go on", { kind: "go_on" }, ["bye", "the wizard's go on"]],
  ])("%s", (_, command, expected) => {
    const moved = stepVisits(simulate(waitProtocol, [{ kind: "start" }, command]).log).map((v) => [
      v.stepId,
      moveWords(v.move),
    ]);
    expect(moved.at(-1)).toEqual(expected);
  });
});
