// What a kappa counted: the slice length and the window of each trial. Kept
// with the coding scheme, so the Results tab and the methods text report one
// figure the same way, and the window is said beside the value.
import { z } from "zod";

/** Which part of each trial agreement counts: the whole trial, from when both observers had coded, or chosen steps. */
export const AGREEMENT_WINDOWS = ["trial", "bothCoding", "steps"] as const;
export type AgreementWindow = (typeof AGREEMENT_WINDOWS)[number];

/** The window as a report names it, beside the kappa. */
export const WINDOW_WORDS: Record<AgreementWindow, string> = {
  trial: "the whole trial",
  bothCoding: "from when both observers had coded",
  steps: "the chosen steps only",
};

export const countedSchema = z.object({
  sliceMs: z.number().int().min(100).max(60_000).default(1000),
  window: z.enum(AGREEMENT_WINDOWS, { error: `must be one of ${AGREEMENT_WINDOWS.join(", ")}` }).default("trial"),
  /** The steps counted, for the "steps" window. */
  stepIds: z.array(z.string().max(100)).max(200).default([]),
});
export type Counted = z.infer<typeof countedSchema>;

/** A scheme no one has chosen for yet: 1 s slices over the whole trial. */
export const COUNTED_BY_DEFAULT: Counted = { sliceMs: 1000, window: "trial", stepIds: [] };

/** "1 s slices, the whole trial", or with steps "1 s slices, steps Story, Recall" (`steps`: every step's name by id). */
export function countedWords(counted: Counted, steps: Array<{ id: string; name: string }>): string {
  const chosen = steps.filter((s) => counted.stepIds.includes(s.id)).map((s) => s.name);
  const which =
    counted.window === "steps" ? `steps ${chosen.join(", ") || "(none chosen)"}` : WINDOW_WORDS[counted.window];
  return `${counted.sliceMs / 1000} s slices, ${which}`;
}

/** Whether two choices count the same slices (as stored, in jsonb's order of keys, or as chosen). */
export function sameCount(a: Counted, b: Counted): boolean {
  return (
    a.sliceMs === b.sliceMs &&
    a.window === b.window &&
    a.stepIds.length === b.stepIds.length &&
    a.stepIds.every((id) => b.stepIds.includes(id))
  );
}
