// The trial's append-only log in PostgreSQL. An event exists once its
// transaction commits; only then may anyone be told about it.
import { and, asc, eq, gt, inArray } from "drizzle-orm";
import type { EngineEvent, StoredEvent } from "@/core/trial";
import type { Database } from "./client";
import { trialEvents, type trials } from "./schema";

export const NOTIFY_CHANNEL = "hri_trial_events";

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

/** The trial status each event moves the trial to (the rest leave it as it is). */
export const STATUS_AFTER: Partial<Record<EngineEvent["type"], (typeof trials.$inferSelect)["status"]>> = {
  "trial.started": "in_progress",
  "trial.paused": "paused",
  "trial.emergency_stop": "paused",
  "trial.resumed": "in_progress",
  "trial.completed": "completed",
  "trial.aborted": "aborted",
};

/** Where a trial's log stands: its owner (one runtime process) keeps this in memory. */
export interface TrialCursor {
  id: string;
  lastSeq: number;
  t0: Date | null;
}

/**
 * Appends events after `cursor.lastSeq` and moves the trial's status, in ONE
 * statement (one round trip, one commit): this sits on the wizard's
 * trigger-to-robot path. (trial, seq) is the primary key, so a second writer
 * holding a stale cursor can never write seq N again: its append fails whole.
 */
export async function appendEvents(
  db: Database,
  cursor: TrialCursor,
  events: EngineEvent[],
  actorId: string | null,
  now: () => Date = () => new Date(),
): Promise<StoredEvent[]> {
  if (events.length === 0) return [];
  const at = now();
  let t0 = cursor.t0;
  let status: string | null = null;
  const rows = events.map((event, i) => {
    if (event.type === "trial.started") t0 ??= at;
    status = STATUS_AFTER[event.type] ?? status;
    return {
      trial_id: cursor.id,
      seq: cursor.lastSeq + i + 1,
      type: event.type,
      server_time: at,
      rel_ms: t0 ? at.getTime() - t0.getTime() : null,
      actor_id: actorId,
      step_id: "stepId" in event ? event.stepId : null,
      action_id: "actionId" in event ? event.actionId : null,
      payload: event,
      deviation: Boolean(event.deviation),
    };
  });
  const ended = status === "completed" || status === "aborted";
  // Drizzle's client leaves serialising to Drizzle, so values go as text PostgreSQL casts by column.
  const wire = rows.map((r) => ({
    ...r,
    server_time: r.server_time.toISOString(),
    payload: JSON.stringify(r.payload),
  }));
  const client = db.$client;
  await client`
    with appended as (
      insert into trial_events ${client(wire, "trial_id", "seq", "type", "server_time", "rel_ms", "actor_id", "step_id", "action_id", "payload", "deviation")}
    ), moved as (
      update trials set
        t0 = coalesce(t0, ${t0?.toISOString() ?? null}::timestamptz),
        status = coalesce(${status}, status),
        ended_at = case when ${ended} then coalesce(ended_at, ${at.toISOString()}::timestamptz) else ended_at end
      where id = ${cursor.id}
    )
    select pg_notify(${NOTIFY_CHANNEL}, ${`${cursor.id}:${cursor.lastSeq + rows.length}`})`;
  return rows.map((r) => ({
    ...r.payload,
    seq: r.seq,
    relMs: r.rel_ms,
    trialId: r.trial_id,
    serverTime: r.server_time,
    actorId: r.actor_id,
  }));
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

/** Every event of several trials in one query, each trial's in order: what exports read a batch of trials with. */
export async function eventsOfTrials(db: Database, trialIds: string[]): Promise<Map<string, StoredEvent[]>> {
  const byTrial = new Map<string, StoredEvent[]>(trialIds.map((id) => [id, []]));
  if (!trialIds.length) return byTrial;
  const rows = await db
    .select()
    .from(trialEvents)
    .where(inArray(trialEvents.trialId, trialIds))
    .orderBy(asc(trialEvents.trialId), asc(trialEvents.seq));
  for (const row of rows) byTrial.get(row.trialId)!.push(toStored(row));
  return byTrial;
}
