import { describe, expect, it } from "vitest";
import { readSettings, settingsProblems, type StudySettings } from "./settings";
import { templateSettings } from "./template";

// A source with every setting away from its default, so what is reset shows.
const source: StudySettings = readSettings({
  requireConsent: false,
  assignment: { strategy: "balanced", perCondition: 3, seed: "source-seed" },
  blinding: { conditionsFromWizards: true, resultsUntilComplete: true },
  demographics: [{ key: "experience", label: "Programming experience", type: "choice", options: ["none", "some"] }],
  consentDocumentVersion: "2b",
});
const copied = templateSettings(source, () => "new-seed");

describe("a study from a template", () => {
  it.each<[string, (s: StudySettings) => unknown, unknown]>([
    ["keeps whether consent is required", (s) => s.requireConsent, false],
    ["keeps the assignment strategy", (s) => s.assignment.strategy, "balanced"],
    ["keeps the block size", (s) => s.assignment.perCondition, 3],
    ["makes a new seed, never the source's", (s) => s.assignment.seed, "new-seed"],
    [
      "keeps the blinds",
      (s) => s.blinding,
      { conditionsFromWizards: true, resultsUntilComplete: true, conditionsFromObservers: false },
    ],
    ["keeps the demographic questions", (s) => s.demographics.map((d) => d.key), ["experience"]],
    ["starts the consent document again at its first version", (s) => s.consentDocumentVersion, "1"],
  ])("%s", (_what, read, expected) => {
    expect(read(copied)).toEqual(expected);
  });

  it("shares nothing with the source's settings, so changing one leaves the other", () => {
    copied.demographics[0]!.options.push("lots");
    copied.blinding.conditionsFromWizards = false;
    expect(source.demographics[0]!.options).toEqual(["none", "some"]);
    expect(source.blinding.conditionsFromWizards).toBe(true);
  });

  it("keeps stratified assignment with the demographic question it stratifies by", () => {
    const stratified = readSettings({
      assignment: { strategy: "stratified", perCondition: 1, stratifyBy: "experience", seed: "source-seed" },
      demographics: source.demographics,
    });
    const made = templateSettings(stratified, () => "new-seed");
    expect(made.assignment).toEqual({
      strategy: "stratified",
      perCondition: 1,
      stratifyBy: "experience",
      seed: "new-seed",
    });
    expect(settingsProblems(made)).toEqual([]);
  });

  it("gives a source with default settings a seed all the same", () => {
    expect(templateSettings(readSettings({}), () => "s").assignment).toEqual({
      strategy: "fixed",
      perCondition: 1,
      seed: "s",
    });
  });
});
