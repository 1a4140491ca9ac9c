// The condition a trial runs in, by name: its participant's condition that runs
// the trial's experiment (between subjects the one, within subjects the one of
// their order). Its variants are what the trial runs (core/protocol/variants.ts).
// Asked by the runtime as it opens a trial and by the web server as it shows or exports one.
import { and, eq, inArray, or, sql } from "drizzle-orm";
import type { Database } from "./client";
import { conditions, participants, trials } from "./schema";

/** Each of these trials' condition name; a trial of no condition (a rehearsal, no participant) is absent. */
export async function conditionsOfTrials(db: Pick<Database, "select">, trialIds: string[]) {
  if (!trialIds.length) return new Map<string, string>();
  const rows = await db
    .select({ trialId: trials.id, name: conditions.name })
    .from(trials)
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .innerJoin(
      conditions,
      and(
        eq(conditions.experimentId, trials.experimentId),
        or(
          eq(conditions.id, participants.conditionId),
          sql`${participants.conditionOrder} @> jsonb_build_array(${conditions.id})`,
        ),
      ),
    )
    .where(inArray(trials.id, trialIds));
  return new Map(rows.map((r) => [r.trialId, r.name]));
}

export async function conditionOfTrial(db: Pick<Database, "select">, trialId: string): Promise<string | null> {
  return (await conditionsOfTrials(db, [trialId])).get(trialId) ?? null;
}
