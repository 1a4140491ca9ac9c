import { describe, expect, it } from "vitest";
import { simulate } from "../trial";
import { trialNames } from "./names";
import { done, perfect, protocol } from "./test-trial";

// The shared test protocol gives none of its actions a label.
const run = simulate(
  protocol,
  [
    ...perfect.slice(0, 2),
    { kind: "unscripted", actionId: "u1", actionType: "nod", parameters: {} },
    ...perfect.slice(2),
  ],
  (i) => i * 100,
).log;
const names = trialNames(protocol, run);

describe("the names a trial's events are about", () => {
  it.each([
    ["a step", { type: "step.entered", stepId: "ask" }, { stepName: "Question" }],
    [
      "speech",
      { type: "action.requested", stepId: "intro", actionId: "hello" },
      { stepName: "Introduction", actionName: "Say: Hello" },
    ],
    ["a gesture, by its action id alone", { type: "action.completed", actionId: "wave" }, { actionName: "Wave" }],
    [
      "an answer",
      { type: "answer.recorded", stepId: "ask", actionId: "answer" },
      { stepName: "Question", actionName: "Record answer" },
    ],
    ["an unscripted action", { type: "action.completed", actionId: "u1" }, { actionName: "Nod" }],
    ["an event about neither", { type: "trial.started" }, {}],
    ["an id the trial does not know", { type: "action.completed", actionId: "gone" }, {}],
  ])("%s", (_, event, expected) => {
    expect(names.of(event)).toEqual(expected);
  });

  it("names every step and action event of a run whose actions have no labels", () => {
    const about = run.filter((e) => "actionId" in e || "stepId" in e);
    expect(about.length).toBeGreaterThan(10);
    for (const e of about) expect(names.of(e).actionName ?? names.of(e).stepName).toMatch(/\w/);
  });

  // Two unscripted lines reported on after the steps went on, and a second request of one id (refused: not logged).
  const unscripted = (actionId: string, text: string) =>
    ({ kind: "unscripted", actionId, actionType: "say", parameters: { text } }) as const;
  const long = simulate(
    protocol,
    [
      ...perfect.slice(0, 2),
      unscripted("u1", "One"),
      unscripted("u2", "Two"),
      ...perfect.slice(2, 5),
      ...done("u2"),
      unscripted("u1", "Again"),
      ...done("u1"),
      ...perfect.slice(5),
    ],
    (i) => i * 100,
  ).log;
  it.each([1, 2, 3, 5, long.length])("names a log read %i events at a time as the whole log names it", (size) => {
    const whole = trialNames(protocol, long);
    const paged = trialNames(protocol, []);
    const named: object[] = [];
    for (let at = 0; at < long.length; at += size) {
      const page = long.slice(at, at + size);
      paged.learn(page);
      named.push(...page.map((e) => paged.of(e)));
    }
    expect(named).toEqual(long.map((e) => whole.of(e)));
    expect(named).toContainEqual({ actionName: "Say: Two" });
    expect(named).toContainEqual({ stepName: "Introduction", actionName: "Say: One" });
  });
});
