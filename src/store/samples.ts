// The robot state samples logged during trials, as the exports and the
// analysis API read them back: by trial, then in time order (ties in the order
// they were written).
import { and, asc, eq, inArray, lte, max } from "drizzle-orm";
import type { Database } from "./client";
import { after, keyedPages } from "./pages";
import { trialSamples } from "./schema";

/** Every sample of these trials in one query. */
export async function samplesOfTrials(db: Database, trialIds: string[]) {
  if (!trialIds.length) return [];
  return db
    .select({
      trialId: trialSamples.trialId,
      topic: trialSamples.topic,
      relMs: trialSamples.relMs,
      data: trialSamples.data,
    })
    .from(trialSamples)
    .where(inArray(trialSamples.trialId, trialIds))
    .orderBy(asc(trialSamples.trialId), asc(trialSamples.relMs), asc(trialSamples.id));
}

/** The id of the trial's last sample (0 before the first): where a file read page by page stops. */
export async function lastSampleOf(db: Database, trialId: string): Promise<number> {
  const [row] = await db
    .select({ id: max(trialSamples.id) })
    .from(trialSamples)
    .where(eq(trialSamples.trialId, trialId));
  return row?.id ?? 0;
}

/** One trial's samples a page at a time (see keyedPages), none logged after sample `upTo`; each with its id, the key. */
export function samplePages(db: Database, trialId: string, page: { limit: number; upTo: number }) {
  const key = [trialSamples.relMs, trialSamples.id];
  return keyedPages(
    (from) =>
      db
        .select({ topic: trialSamples.topic, relMs: trialSamples.relMs, data: trialSamples.data, id: trialSamples.id })
        .from(trialSamples)
        .where(and(eq(trialSamples.trialId, trialId), lte(trialSamples.id, page.upTo), after(key, from)))
        .orderBy(asc(trialSamples.relMs), asc(trialSamples.id))
        .limit(page.limit),
    (s) => [s.relMs, s.id],
    page.limit,
  );
}
