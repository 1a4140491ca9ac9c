import { describe, expect, it } from "vitest";
import {
  changedSettings,
  readSettings,
  settingsProblems,
  studySettingsChangeSchema,
  studySettingsSchema,
  type StudySettings,
} from "./settings";

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

describe("settings that do not fit together", () => {
  const question = (type: "choice" | "text") => ({
    key: "experience",
    label: "Programming experience",
    type,
    options: type === "choice" ? ["none", "some", "a lot"] : [],
  });
  it.each<[string, Partial<StudySettings["assignment"]>, ReturnType<typeof question>[], string[]]>([
    ["balanced needs nothing more", { strategy: "balanced" }, [], []],
    ["stratified by a choice question", { strategy: "stratified", stratifyBy: "experience" }, [question("choice")], []],
    [
      "stratified by nothing",
      { strategy: "stratified" },
      [question("choice")],
      ["Assignment: stratified assignment needs a demographic question to stratify by"],
    ],
    [
      "stratified by a question the study does not ask",
      { strategy: "stratified", stratifyBy: "age" },
      [question("choice")],
      ['Assignment: "age" is not a demographic question of this study'],
    ],
    [
      "stratified by free text",
      { strategy: "stratified", stratifyBy: "experience" },
      [question("text")],
      ["Assignment: Programming experience must be a choice question to stratify by (it is text)"],
    ],
  ])("%s", (_, assignment, demographics, problems) => {
    const settings = studySettingsSchema.parse({ assignment: { perCondition: 1, ...assignment }, demographics });
    expect(settingsProblems(settings)).toEqual(problems);
  });
});
