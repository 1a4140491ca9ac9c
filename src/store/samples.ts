// The robot state samples logged during trials, as the exports and the
// analysis API read them back.
import { asc, inArray } from "drizzle-orm";
import type { Database } from "./client";
import { trialSamples } from "./schema";

/** Every sample of these trials in one query: by trial, then in time order (ties in the order they were written). */
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
