import { describe, expect, it } from "vitest";
import { simulate } from "../trial";
import { trialNames } from "./names";
import { perfect, protocol } from "./test-trial";

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
});
