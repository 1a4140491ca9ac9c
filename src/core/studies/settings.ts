// A study's switches, stored as JSON on the study and read through here so a
// missing or older settings object always means the safe default.
import { z } from "zod";

export const studySettingsSchema = z.object({
  /** Trials need a participant whose consent is recorded as given. */
  requireConsent: z.boolean().default(true),
});

export type StudySettings = z.infer<typeof studySettingsSchema>;

export function readSettings(stored: unknown): StudySettings {
  const parsed = studySettingsSchema.safeParse(stored ?? {});
  return parsed.success ? parsed.data : studySettingsSchema.parse({});
}
