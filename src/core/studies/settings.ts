// A study's switches, stored as JSON on the study and read through here so a
// missing or older settings object always means the safe default.
import { z } from "zod";

export const ASSIGNMENT_STRATEGIES = ["fixed", "random", "balanced", "counterbalanced"] as const;

export const assignmentSettingsSchema = z.object({
  strategy: z.enum(ASSIGNMENT_STRATEGIES, { error: `must be one of ${ASSIGNMENT_STRATEGIES.join(", ")}` }),
  /** Balanced only: how often each condition appears in one block. */
  perCondition: z.number().int().min(1, "must be at least 1").max(20, "must be at most 20").default(1),
  /** Made by the server when the strategy is chosen; with it, anyone can reproduce the assignments. */
  seed: z.string().min(1).max(200).optional(),
});

export const studySettingsSchema = z.object({
  /** Trials need a participant whose consent is recorded as given. */
  requireConsent: z.boolean().default(true),
  assignment: assignmentSettingsSchema.default({ strategy: "fixed", perCondition: 1 }),
});

export type StudySettings = z.infer<typeof studySettingsSchema>;

export function readSettings(stored: unknown): StudySettings {
  const parsed = studySettingsSchema.safeParse(stored ?? {});
  return parsed.success ? parsed.data : studySettingsSchema.parse({});
}
