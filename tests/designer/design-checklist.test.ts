// The design checklist scorer, checked on the demo Storyteller and on
// designs that miss one item each: a scorer that always says 100 proves nothing.
import { describe, expect, it } from "vitest";
import { exportExperiment } from "../../src/core/designer/exchange";
import type { DesignDraft } from "../../src/core/designer/types";
import { storytellerDraft } from "../../src/server/seed/storyteller";
import { scoreDesign } from "../support/storyteller-design-checklist";

const without = (change: (d: DesignDraft) => void) => {
  const d = structuredClone(storytellerDraft());
  change(d);
  return scoreDesign(exportExperiment(d));
};

describe("the Storyteller design checklist", () => {
  it("gives the demo experiment 100", () => {
    expect(scoreDesign(exportExperiment(storytellerDraft()))).toEqual({ score: 100, failed: [] });
  });

  it.each([
    ["a changed intro text", (d: DesignDraft) => (d.steps[0]!.actions[0]!.parameters = { text: "Hi." }), 90],
    ["no wave", (d: DesignDraft) => d.steps[0]!.actions.splice(1, 1), 90],
    ["no narrative gesture", (d: DesignDraft) => d.steps[1]!.actions.splice(1, 1), 90],
    ["the branch taken out (the wizard would jump by hand)", (d: DesignDraft) => d.steps[2]!.actions.splice(3, 1), 85],
    ["a nod where the head shake should be", (d: DesignDraft) => (d.steps[4]!.actions[1]!.type = "nod"), 90],
    ["the steps in reverse order", (d: DesignDraft) => d.steps.reverse(), 65],
  ])("takes points off for %s", (_name, change, score) => {
    expect(without(change).score).toBe(score);
  });
});
