import { describe, expect, it } from "vitest";
import { changedSettings, readSettings, studySettingsChangeSchema, type StudySettings } from "./settings";

// A study with every setting away from its default, so a default filled in shows.
const before: StudySettings = readSettings({
  requireConsent: false,
  assignment: { strategy: "balanced", perCondition: 3, seed: "old-seed" },
  blinding: { conditionsFromWizards: true, resultsUntilComplete: true },
  demographics: [{ key: "age", label: "Age", type: "number" }],
  consentDocumentVersion: "2b",
});

/** The change as the procedure receives it: through its input schema. */
const apply = (change: unknown) => changedSettings(before, studySettingsChangeSchema.parse(change), () => "new-seed");

describe("a settings change touches only what it names", () => {
  it.each<[string, unknown, Partial<StudySettings>]>([
    ["nothing", {}, {}],
    ["consent required", { requireConsent: true }, { requireConsent: true }],
    [
      "one blind",
      { blinding: { resultsUntilComplete: false } },
      { blinding: { conditionsFromWizards: true, resultsUntilComplete: false } },
    ],
    [
      "the other blind",
      { blinding: { conditionsFromWizards: false } },
      { blinding: { conditionsFromWizards: false, resultsUntilComplete: true } },
    ],
    [
      "the strategy (a new seed, the block size kept)",
      { assignment: { strategy: "random" } },
      { assignment: { strategy: "random", perCondition: 3, seed: "new-seed" } },
    ],
    [
      "the block size (a new seed)",
      { assignment: { perCondition: 2 } },
      { assignment: { strategy: "balanced", perCondition: 2, seed: "new-seed" } },
    ],
    ["the consent document", { consentDocumentVersion: "3" }, { consentDocumentVersion: "3" }],
    ["the demographic fields", { demographics: [] }, { demographics: [] }],
  ])("%s", (_, change, changed) => {
    expect(apply(change)).toEqual({ ...before, ...changed });
  });
});
