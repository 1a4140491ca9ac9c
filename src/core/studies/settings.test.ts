import { describe, expect, it } from "vitest";
import {
  changedSettings,
  readSettings,
  settingsProblems,
  shownTitle,
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
      { blinding: { conditionsFromWizards: true, resultsUntilComplete: false, conditionsFromObservers: false } },
    ],
    [
      "the other blind",
      { blinding: { conditionsFromWizards: false } },
      { blinding: { conditionsFromWizards: false, resultsUntilComplete: true, conditionsFromObservers: false } },
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
    [
      "the observers' blind",
      { blinding: { conditionsFromObservers: true } },
      { blinding: { conditionsFromWizards: true, resultsUntilComplete: true, conditionsFromObservers: true } },
    ],
    [
      "a seed of the team's own, trimmed",
      { assignment: { seed: " prereg-2026 " } },
      { assignment: { strategy: "balanced", perCondition: 3, seed: "prereg-2026" } },
    ],
    ["the consent checkbox's words", { consentAgreement: "I consent" }, { consentAgreement: "I consent" }],
    ["the neutral name", { neutralTitle: "A study of storytelling" }, { neutralTitle: "A study of storytelling" }],
  ])("%s", (_, change, changed) => {
    expect(apply(change)).toEqual({ ...before, ...changed });
  });
});

describe("the study's name as shown", () => {
  it.each<[string, string, boolean, string]>([
    ["no neutral name", "", true, "Politeness and trust H2"],
    ["a neutral name, to a participant", "A study of storytelling", true, "A study of storytelling"],
    ["a neutral name, to the research team", "A study of storytelling", false, "Politeness and trust H2"],
  ])("%s", (_, neutralTitle, neutral, shown) => {
    expect(shownTitle("Politeness and trust H2", { ...before, neutralTitle }, neutral)).toBe(shown);
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

describe("a change the settings refuse, naming the field", () => {
  it.each<[string, unknown, string]>([
    ["an empty seed", { assignment: { seed: "  " } }, "assignment.seed: must not be empty"],
    ["a seed too long", { assignment: { seed: "x".repeat(201) } }, "assignment.seed: must be at most 200 characters"],
    ["no words to agree with", { consentAgreement: "" }, "consentAgreement: must not be empty"],
    ["a neutral name too long", { neutralTitle: "x".repeat(201) }, "neutralTitle: must be at most 200 characters"],
    [
      "a blind that is not yes or no",
      { blinding: { conditionsFromObservers: "yes" } },
      "blinding.conditionsFromObservers",
    ],
  ])("%s", (_, change, problem) => {
    const parsed = studySettingsChangeSchema.safeParse(change);
    expect(parsed.success).toBe(false);
    const issue = parsed.error!.issues[0]!;
    expect(`${issue.path.join(".")}: ${issue.message}`).toContain(problem);
  });
});
