// A study's switches, stored as JSON on the study and read through here so a
// missing or older settings object always means the safe default.
import { z } from "zod";

export const ASSIGNMENT_STRATEGIES = ["fixed", "random", "balanced", "stratified", "counterbalanced"] as const;

const assignmentFields = {
  strategy: z.enum(ASSIGNMENT_STRATEGIES, { error: `must be one of ${ASSIGNMENT_STRATEGIES.join(", ")}` }),
  /** Balanced and stratified: how often each condition appears in one block. */
  perCondition: z.number().int().min(1, "must be at least 1").max(20, "must be at most 20"),
  /** Stratified only: the key of the demographic choice field whose answers are the strata. */
  stratifyBy: z
    .string()
    .regex(/^[a-z][a-z0-9_]{0,39}$/, "must be the key of a demographic field")
    .optional(),
  /**
   * Made by the server when the strategy is chosen, or set by the team before
   * the first assignment (a preregistered seed); with it, anyone can reproduce
   * the assignments.
   */
  seed: z.string().trim().min(1, "must not be empty").max(200, "must be at most 200 characters").optional(),
};

export const assignmentSettingsSchema = z.object({
  ...assignmentFields,
  perCondition: assignmentFields.perCondition.default(1),
});

const blindingFields = {
  /** Wizards never see which condition (or experiment) a session runs. */
  conditionsFromWizards: z.boolean(),
  /** Researchers and observers see no results until the study is marked completed. */
  resultsUntilComplete: z.boolean(),
  /** Observers (coders) never see which condition a session runs, nor anything that names it. */
  conditionsFromObservers: z.boolean(),
};

export const blindingSchema = z.object({
  conditionsFromWizards: blindingFields.conditionsFromWizards.default(false),
  resultsUntilComplete: blindingFields.resultsUntilComplete.default(false),
  conditionsFromObservers: blindingFields.conditionsFromObservers.default(false),
});

export const DEMOGRAPHIC_TYPES = ["text", "number", "choice"] as const;

/** A demographic question the study asks of each participant; answers are optional. */
export const demographicFieldSchema = z.object({
  key: z.string().regex(/^[a-z][a-z0-9_]{0,39}$/, "must be lower-case letters, digits and _ (starting with a letter)"),
  label: z.string().trim().min(1, "must not be empty").max(100, "must be at most 100 characters"),
  type: z.enum(DEMOGRAPHIC_TYPES, { error: `must be one of ${DEMOGRAPHIC_TYPES.join(", ")}` }),
  options: z.array(z.string().trim().min(1).max(100)).max(30).default([]),
});

export type DemographicField = z.infer<typeof demographicFieldSchema>;

const settingFields = {
  /** Trials need a participant whose consent is recorded as given. */
  requireConsent: z.boolean(),
  assignment: assignmentSettingsSchema,
  blinding: blindingSchema,
  demographics: z.array(demographicFieldSchema).max(30, "at most 30 fields"),
  /** The consent document participants agree to now; each consent records the version it was. */
  consentDocumentVersion: z.string().trim().min(1, "must not be empty").max(50, "must be at most 50 characters"),
  /** The words beside the consent checkbox on the participant's page. */
  consentAgreement: z.string().trim().min(1, "must not be empty").max(300, "must be at most 300 characters"),
  /** What participants (and condition-blind wizards and observers) see in place of the study's title; empty: the title. */
  neutralTitle: z.string().trim().max(200, "must be at most 200 characters"),
};

export const studySettingsSchema = z.object({
  requireConsent: settingFields.requireConsent.default(true),
  assignment: settingFields.assignment.default({ strategy: "fixed", perCondition: 1 }),
  blinding: settingFields.blinding.default({
    conditionsFromWizards: false,
    resultsUntilComplete: false,
    conditionsFromObservers: false,
  }),
  demographics: settingFields.demographics.default([]),
  consentDocumentVersion: settingFields.consentDocumentVersion.default("1"),
  consentAgreement: settingFields.consentAgreement.default("I agree to take part"),
  neutralTitle: settingFields.neutralTitle.default(""),
});

/**
 * A change to some settings: the keys given and nothing else, down to each
 * blind and each assignment field. No defaults here: zod fills a default in
 * for a key left out, and that would overwrite what the study has.
 */
export const studySettingsChangeSchema = z
  .object({
    ...settingFields,
    assignment: z.object(assignmentFields).partial(),
    blinding: z.object(blindingFields).partial(),
  })
  .partial();

export type StudySettingsChange = z.infer<typeof studySettingsChangeSchema>;

/**
 * The settings after a change: what it names, and everything else as it was.
 * A changed assignment gets a fresh seed unless the change gives one, so each
 * choice of strategy has its own reproducible sequence.
 */
export function changedSettings(
  before: StudySettings,
  change: StudySettingsChange,
  newSeed: () => string,
): StudySettings {
  const { assignment, blinding, ...rest } = change;
  return {
    ...before,
    ...rest,
    assignment: assignment
      ? { ...before.assignment, ...assignment, seed: assignment.seed ?? newSeed() }
      : before.assignment,
    blinding: { ...before.blinding, ...blinding },
  };
}

export type StudySettings = z.infer<typeof studySettingsSchema>;
export type AssignmentSettings = StudySettings["assignment"];

/**
 * What is wrong with settings as a whole, as "where: reason". Strata need a
 * question with a fixed set of answers, asked by the study: free text would
 * make a group of one per spelling.
 */
export function settingsProblems(settings: StudySettings): string[] {
  const { strategy, stratifyBy } = settings.assignment;
  if (strategy !== "stratified") return [];
  const field = settings.demographics.find((f) => f.key === stratifyBy);
  if (!stratifyBy) return ["Assignment: stratified assignment needs a demographic question to stratify by"];
  if (!field) return [`Assignment: "${stratifyBy}" is not a demographic question of this study`];
  if (field.type !== "choice")
    return [`Assignment: ${field.label} must be a choice question to stratify by (it is ${field.type})`];
  return [];
}

/** The study's name as a participant, or a caller blind to its conditions, sees it. */
export function shownTitle(title: string, settings: StudySettings, neutral: boolean): string {
  return neutral && settings.neutralTitle ? settings.neutralTitle : title;
}

export function readSettings(stored: unknown): StudySettings {
  const parsed = studySettingsSchema.safeParse(stored ?? {});
  return parsed.success ? parsed.data : studySettingsSchema.parse({});
}
