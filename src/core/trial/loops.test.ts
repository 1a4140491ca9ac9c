import { describe, expect, it } from "vitest";
import type { After, Onward } from "../protocol/document";
import { type Command, type EngineEvent, fold, rehearse, simulate, type TrialProtocol, upcoming } from "./index";

// "Ask again, at most twice, then …": the question step goes back to itself.
const protocol = (onward: Onward, limit?: After): TrialProtocol => ({
  steps: [
    { id: "intro", name: "Hello", actions: [{ id: "hi", type: "say", parameters: { text: "Hi" } }] },
    {
      id: "ask",
      name: "Question",
      after: { to: "again", stepId: "ask", times: 2, onward },
      ...(limit ? { timeLimit: { seconds: 10, after: limit } } : {}),
      actions: [{ id: "q", type: "say", parameters: { text: "What color?" } }],
    },
    { id: "bye", name: "Goodbye", actions: [{ id: "bye-say", type: "say", parameters: { text: "Bye" } }] },
  ],
});
const onNext = protocol({ to: "next" });

const say = (id: string): Command[] => [{ kind: "next" }, { kind: "completed", actionId: id }];
const asking: Command[] = [{ kind: "start" }, ...say("hi"), { kind: "next" }];
/** The question asked and the wizard's next after it: the step's way on taken once. */
const round: Command[] = [...say("q"), { kind: "next" }];

const brief = (events: EngineEvent[] | string) =>
  typeof events === "string"
    ? events
    : events
        .filter((e) => !e.type.startsWith("timer."))
        .map((e) => {
          if (e.type === "step.entered") return [e.type, e.stepId, e.via, e.loop ?? null, e.deviation ?? null];
          if (e.type === "loop.bound_reached") return [e.type, e.stepId, e.loop, e.times];
          return [e.type, e.deviation ?? null];
        });

describe("a bounded loop", () => {
  it.each<[string, TrialProtocol, Command[], unknown]>([
    [
      "the first time, the step's way on goes back to it",
      onNext,
      [...asking, ...round],
      [["step.entered", "ask", "loop", "after:ask", null]],
    ],
    [
      "while it has gone back fewer times than its bound, it goes back again",
      onNext,
      [...asking, ...round, ...round],
      [["step.entered", "ask", "loop", "after:ask", null]],
    ],
    [
      "its bound reached, the trial takes its way on: the next step",
      onNext,
      [...asking, ...round, ...round, ...round],
      [
        ["loop.bound_reached", "ask", "after:ask", 2],
        ["step.entered", "bye", "loop_bound", "after:ask", null],
      ],
    ],
    [
      "its bound reached, a way on to the end ends the trial, as designed (no deviation)",
      protocol({ to: "end" }),
      [...asking, ...round, ...round, ...round],
      [
        ["loop.bound_reached", "ask", "after:ask", 2],
        ["trial.completed", null],
      ],
    ],
    [
      "the wizard's jump inside the loop is not a time round it: the loop still goes back",
      onNext,
      [...asking, ...round, { kind: "jump", stepId: "intro" }, ...say("hi"), { kind: "next" }, ...round],
      [["step.entered", "ask", "loop", "after:ask", null]],
    ],
    [
      "and goes back only as often as its bound, counted from the log",
      onNext,
      [...asking, ...round, { kind: "jump", stepId: "intro" }, ...say("hi"), { kind: "next" }, ...round, ...round],
      [
        ["loop.bound_reached", "ask", "after:ask", 2],
        ["step.entered", "bye", "loop_bound", "after:ask", null],
      ],
    ],
    [
      "a time limit whose way on is a loop goes back when it runs out",
      protocol({ to: "next" }, { to: "again", stepId: "intro", times: 1, onward: { to: "end" } }),
      [...asking, { kind: "timer_fired", timerId: "step:ask:2" }],
      [["step.entered", "intro", "loop", "time:ask", null]],
    ],
    [
      "and, its own bound reached, takes its way on; the step's own loop is counted apart",
      protocol({ to: "next" }, { to: "again", stepId: "intro", times: 1, onward: { to: "end" } }),
      [
        ...asking,
        { kind: "timer_fired", timerId: "step:ask:2" },
        ...say("hi"),
        { kind: "next" },
        { kind: "timer_fired", timerId: "step:ask:4" },
      ],
      [
        ["loop.bound_reached", "ask", "time:ask", 1],
        ["trial.completed", null],
      ],
    ],
  ])("%s", (_, design, commands, expected) => {
    expect(brief(simulate(design, commands).last)).toEqual(expected);
  });

  it("keeps how many times each loop went back, and resumes from its log to the same count", () => {
    const { log } = simulate(onNext, [...asking, ...round, ...round]);
    const state = fold(onNext, log);
    expect(state.loops).toEqual({ "after:ask": 2 });
    expect(state.path).toEqual(["intro", "ask", "ask", "ask"]);
    // What the wizard is told comes next follows the count: the bound is reached, so the next step.
    expect(upcoming(onNext, state)).toMatchObject({ kind: "step", step: { id: "bye" } });
    expect(upcoming(onNext, fold(onNext, log.slice(0, -1)))).toMatchObject({ kind: "step", step: { id: "ask" } });
  });

  it("logs each time round and the bound as the protocol, never as a deviation", () => {
    const { log } = simulate(onNext, [...asking, ...round, ...round, ...round]);
    expect(log.filter((e) => e.deviation)).toEqual([]);
    expect(log.filter((e) => e.type === "step.entered" && e.via === "loop")).toHaveLength(2);
  });

  it.each<[string, TrialProtocol, string[]]>([
    ["rehearsal walks the loop to its bound, then on", onNext, ["intro", "ask", "ask", "ask", "bye"]],
    ["or to the end", protocol({ to: "end" }), ["intro", "ask", "ask", "ask"]],
  ])("%s", (_, design, path) => {
    const rehearsal = rehearse(design);
    expect(rehearsal.ending).toBe("completed");
    expect(rehearsal.steps.map((s) => s.stepId)).toEqual(path);
    // Each time back round the loop says which time it is.
    expect(rehearsal.steps.map((s) => s.again)).toEqual([undefined, undefined, 1, 2, undefined].slice(0, path.length));
  });
});
