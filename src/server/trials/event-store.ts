// The trial's append-only log in PostgreSQL. An event exists once its
// transaction commits; only then may anyone be told about it.
import { and, asc, eq, gt, sql } from "drizzle-orm";
import type { EngineEvent, TrialEvent } from "@/core/trial";
import type { Database } from "../db/client";
import { trialEvents, trials } from "../db/schema";

export const NOTIFY_CHANNEL = "hri_trial_events";

export type StoredEvent = TrialEvent & { trialId: string; serverTime: Date; actorId: string | null };

type Row = typeof trialEvents.$inferSelect;

function toStored(row: Row): StoredEvent {
  return {
    // The payload is the engine's event itself, deviation kind included.
    ...(row.payload as EngineEvent),
    seq: row.seq,
    relMs: row.relMs,
    trialId: row.trialId,
    serverTime: row.serverTime,
    actorId: row.actorId,
  };
}

const STATUS_AFTER: Partial<Record<EngineEvent["type"], (typeof trials.$inferSelect)["status"]>> = {
  "trial.started": "in_progress",
  "trial.paused": "paused",
  "trial.emergency_stop": "paused",
  "trial.resumed": "in_progress",
  "trial.completed": "completed",
  "trial.aborted": "aborted",
};

/**
 * Appends events with the next sequence numbers, in one transaction that
 * locks the trial row, so two writers can never both write seq N.
 */
export async function appendEvents(
  db: Database,
  trialId: string,
  events: EngineEvent[],
  actorId: string | null,
  now: () => Date = () => new Date(),
): Promise<StoredEvent[]> {
  if (events.length === 0) return [];
  return db.transaction(async (tx) => {
    const [trial] = await tx.select().from(trials).where(eq(trials.id, trialId)).for("update");
    if (!trial) throw new Error(`Trial ${trialId} does not exist.`);
    const [{ last }] = (await tx
      .select({ last: sql<number>`coalesce(max(${trialEvents.seq}), 0)::int` })
      .from(trialEvents)
      .where(eq(trialEvents.trialId, trialId))) as [{ last: number }];
    const at = now();
    let t0 = trial.t0;
    let status = trial.status;
    let endedAt = trial.endedAt;
    const rows = events.map((event, i) => {
      if (event.type === "trial.started") t0 = at;
      status = STATUS_AFTER[event.type] ?? status;
      if (status === "completed" || status === "aborted") endedAt ??= at;
      return {
        trialId,
        seq: last + i + 1,
        type: event.type,
        serverTime: at,
        relMs: t0 ? at.getTime() - t0.getTime() : null,
        actorId,
        stepId: "stepId" in event ? event.stepId : null,
        actionId: "actionId" in event ? event.actionId : null,
        payload: event,
        deviation: Boolean(event.deviation),
      };
    });
    const inserted = await tx.insert(trialEvents).values(rows).returning();
    await tx.update(trials).set({ t0, status, endedAt }).where(eq(trials.id, trialId));
    // Delivered at commit, to every runtime process listening.
    await tx.execute(sql`select pg_notify(${NOTIFY_CHANNEL}, ${`${trialId}:${last + rows.length}`})`);
    return inserted.map(toStored);
  });
}

/** The events after `afterSeq`, in order: what a reconnecting client missed. */
export async function eventsSince(db: Database, trialId: string, afterSeq = 0): Promise<StoredEvent[]> {
  const rows = await db
    .select()
    .from(trialEvents)
    .where(and(eq(trialEvents.trialId, trialId), gt(trialEvents.seq, afterSeq)))
    .orderBy(asc(trialEvents.seq));
  return rows.map(toStored);
}
