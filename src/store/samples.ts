// The robot state samples logged during trials, written many trials at a
// time, and read back as the exports and the analysis API read them: by trial,
// then in time order (ties in the order they were written).
import { and, asc, eq, inArray, lte, max } from "drizzle-orm";
import type { Database } from "./client";
import { after, keyedPages } from "./pages";
import { trialSamples } from "./schema";

export type SampleRow = typeof trialSamples.$inferInsert;

/**
 * Stores the rows, of any trials, in one statement and one commit. One text whatever the rows (a JSON array
 * the database reads as records), so the driver prepares it once and sends it in one round trip: a
 * statement of many rows built for each batch was parsed and described anew every time. In the given
 * order, so samples at the same time keep the order they came in (their ids).
 */
export async function insertSamples(db: Database, rows: SampleRow[]): Promise<void> {
  if (!rows.length) return;
  const json = JSON.stringify(
    rows.map((r) => ({ trial_id: r.trialId, topic: r.topic, rel_ms: r.relMs, data: r.data })),
  );
  await db.$client`
    insert into trial_samples (trial_id, topic, rel_ms, data)
    select trial_id, topic, rel_ms, data
    from rows from (jsonb_to_recordset(${json}::jsonb) as (trial_id text, topic text, rel_ms double precision, data jsonb))
      with ordinality as r(trial_id, topic, rel_ms, data, n)
    order by n`;
}

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
