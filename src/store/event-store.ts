// The trial's append-only log in PostgreSQL. An event exists once its
// transaction commits; only then may anyone be told about it.
import { and, asc, eq, inArray, isNotNull, max } from "drizzle-orm";
import type { EngineEvent, StoredEvent, TrialEvent } from "@/core/trial";
import type { Database } from "./client";
import { keyedPages } from "./pages";
import { trialEvents, type trials } from "./schema";

export const NOTIFY_CHANNEL = "hri_trial_events";

type Row = typeof trialEvents.$inferSelect;

/**
 * An event as the fold reads it: its body (the payload is the engine's event
 * itself, deviation kind included) with its seq and time since t0, without
 * the trial, server time and actor every stored event repeats. Built on the
 * payload as the driver parsed it for this row alone, not copied: a copy of
 * each of a long log's events cost the analysis page's 100k a fifth of a second.
 */
function toTrialEvent(row: Pick<Row, "seq" | "relMs" | "payload">): TrialEvent {
  return Object.assign(row.payload as EngineEvent, { seq: row.seq, relMs: row.relMs });
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
  /** The owner's epoch (`takeTrial`): its append is refused once another process has taken the trial. */
  epoch?: number;
}

/** Why an owner's append was refused: another process took the trial after it (raised by `hri_fenced`). */
const FENCED = "HR409";

export const fencedOut = (error: unknown) => (error as { code?: string } | null)?.code === FENCED;

/**
 * The trial taken by a runtime process that now holds its lock: its epoch,
 * one more than the last owner's, whose appends are refused from now on. A
 * finished trial's is left as it is (nothing drives its robot; its row is
 * not written by opening it). Null when the trial does not exist.
 */
export async function takeTrial(db: Database, trialId: string): Promise<number | null> {
  const client = db.$client;
  const [row] = await client<[{ epoch: number | null }]>`
    with bumped as (
      update trials set owner_epoch = owner_epoch + 1
      where id = ${trialId} and status not in ('completed', 'aborted')
      returning owner_epoch
    )
    select coalesce((select owner_epoch from bumped), (select owner_epoch from trials where id = ${trialId})) as epoch`;
  return row?.epoch ?? null;
}

/** One trial's share of a write: its events, after its cursor, by whom, answering which request. */
export interface Append {
  cursor: TrialCursor;
  events: EngineEvent[];
  actorId: string | null;
  requestId?: string | null;
  /** The robot's reports a command carries: logged before its events, by no one, answering no request. */
  reports?: EngineEvent[];
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
  options: { now?: () => Date; requestId?: string | null } = {},
): Promise<StoredEvent[]> {
  const [stored] = await appendMany(db, [{ cursor, events, actorId, requestId: options.requestId }], options.now);
  return stored!;
}

/**
 * Several trials' appends in ONE statement, one transaction, one commit
 * (group commit: what arrived while the last commit was under way goes in
 * the next). Each trial keeps its own sequence; all land or none do.
 */
export async function appendMany(
  db: Database,
  appends: Append[],
  now: () => Date = () => new Date(),
): Promise<StoredEvent[][]> {
  const at = now();
  const rows: Array<Omit<ReturnType<typeof rowOf>, "payload"> & { payload: string }> = [];
  const moves = {
    id: [] as string[],
    t0: [] as Array<string | null>,
    status: [] as Array<string | null>,
    epoch: [] as Array<string | null>,
  };
  const notices: string[] = [];
  const stored = appends.map(({ cursor, events, actorId, requestId, reports = [] }) => {
    let t0 = cursor.t0;
    let status: string | null = null;
    const mine = [...reports, ...events].map((event, i) => {
      if (event.type === "trial.started") t0 ??= at;
      status = STATUS_AFTER[event.type] ?? status;
      const ours = i >= reports.length;
      return rowOf(cursor, i, event, at, t0, ours ? actorId : null, ours ? (requestId ?? null) : null);
    });
    if (mine.length) {
      rows.push(...mine.map((r) => ({ ...r, payload: JSON.stringify(r.payload) })));
      moves.id.push(cursor.id);
      moves.t0.push(t0?.toISOString() ?? null);
      moves.status.push(status);
      moves.epoch.push(cursor.epoch === undefined ? null : String(cursor.epoch));
      notices.push(`${cursor.id}:${cursor.lastSeq + mine.length}`);
    }
    return mine.map((r) => ({
      ...r.payload,
      seq: r.seq,
      relMs: r.rel_ms,
      trialId: r.trial_id,
      serverTime: at,
      actorId: r.actor_id,
    }));
  });
  if (rows.length === 0) return stored;
  const client = db.$client;
  // Values go as text, cast by column (Drizzle's client leaves serialising to Drizzle); the trials move
  // by one row each, from parallel arrays. A trial whose epoch moved on (another process took it) is not
  // moved, and the statement fails whole: the update waits for a takeover under way, then sees its epoch.
  await client`
    with appended as (
      insert into trial_events ${client(rows, "trial_id", "seq", "type", "server_time", "rel_ms", "actor_id", "step_id", "action_id", "payload", "deviation", "request_id")}
    ), moved as (
      update trials set
        t0 = coalesce(trials.t0, v.t0::timestamptz),
        status = coalesce(v.status, trials.status),
        ended_at = case when v.status in ('completed', 'aborted') then coalesce(trials.ended_at, ${at.toISOString()}::timestamptz) else trials.ended_at end
      from unnest(${moves.id}::text[], ${moves.t0}::text[], ${moves.status}::text[], ${moves.epoch}::text[]) as v(id, t0, status, epoch)
      where trials.id = v.id and (v.epoch is null or trials.owner_epoch = v.epoch::integer)
      returning trials.id
    )
    select pg_notify(${NOTIFY_CHANNEL}, n) from unnest(${notices}::text[]) as n
    where hri_fenced((select count(*) from moved), ${new Set(moves.id).size})`;
  return stored;
}

function rowOf(
  cursor: TrialCursor,
  i: number,
  event: EngineEvent,
  at: Date,
  t0: Date | null,
  actorId: string | null,
  requestId: string | null,
) {
  return {
    trial_id: cursor.id,
    seq: cursor.lastSeq + i + 1,
    type: event.type,
    server_time: at.toISOString(),
    rel_ms: t0 ? at.getTime() - t0.getTime() : null,
    actor_id: actorId,
    step_id: "stepId" in event ? event.stepId : null,
    action_id: "actionId" in event ? event.actionId : null,
    payload: event,
    deviation: Boolean(event.deviation),
    request_id: requestId,
  };
}

type Page = { limit: number; upTo?: number };
/** The largest seq a log can hold (its column is an integer): "up to" when no page says. */
const LAST_SEQ = 2 ** 31 - 1;

/** A stored event's columns as the driver gives them. */
type LogRow = {
  seq: number;
  rel_ms: number | null;
  server_time: string;
  actor_id: string | null;
  payload: EngineEvent;
};

/** A stored event, built on its payload as the driver parsed it for this row alone (as toTrialEvent). */
function toStored(row: LogRow, trialId: string): StoredEvent {
  return Object.assign(row.payload, {
    seq: row.seq,
    relMs: row.rel_ms,
    trialId,
    // As drizzle has the driver give timestamps: PostgreSQL's text, which Date reads.
    serverTime: new Date(row.server_time),
    actorId: row.actor_id,
  });
}

/** The seq of the trial's last event (0 before the first): where a file read page by page stops. */
export async function lastSeqOf(db: Database, trialId: string): Promise<number> {
  const [row] = await db
    .select({ seq: max(trialEvents.seq) })
    .from(trialEvents)
    .where(eq(trialEvents.trialId, trialId));
  return row?.seq ?? 0;
}

/**
 * The events after `afterSeq`, in order: what a reconnecting client missed.
 * With a `page`, at most `limit` of them (none after seq `upTo` if given): a
 * log too large to hold is read a page at a time, each after the last one's seq.
 */
export async function eventsSince(db: Database, trialId: string, afterSeq = 0, page?: Page): Promise<StoredEvent[]> {
  const sql = db.$client;
  // Straight from the driver, only the columns an event is made of: drizzle's mapping of every column cost
  // opening a trial of 100k events more than half its time (bench/open-large). One text, whatever the page
  // (`limit null` is none), so the driver prepares it once.
  const rows = await sql<LogRow[]>`
    select seq, rel_ms, server_time, actor_id, payload from trial_events
    where trial_id = ${trialId} and seq > ${afterSeq} and seq <= ${page?.upTo ?? LAST_SEQ}
    order by seq limit ${page?.limit ?? null}`;
  return rows.map((row) => toStored(row, trialId));
}

/**
 * The events after `afterSeq`, in order, as the fold reads them (see
 * toTrialEvent): half the bytes of the stored events. Parsed from the text
 * trialLogJson makes, in one go, for the API's callers; the analysis page
 * takes the text itself.
 */
export async function trialLog(db: Database, trialId: string, afterSeq = 0): Promise<TrialEvent[]> {
  let text = "";
  for await (const piece of trialLogJson(db, trialId, afterSeq)) text += piece;
  return JSON.parse(text) as TrialEvent[];
}

/** Events of a log read at a time as JSON text: a page's rows are dropped once written. */
const LOG_PAGE = 5000;

/**
 * The same log as JSON text, in pieces as it is read (an array's opening, a
 * page of events at a time, its close), made from each payload's text as
 * PostgreSQL gives it, never parsed here: for the analysis page's 100k
 * events, parsing each payload and writing it out again cost the server
 * more than reading them, and holding them all at once more still.
 */
export async function* trialLogJson(db: Database, trialId: string, afterSeq = 0): AsyncGenerator<string> {
  type Row = { seq: number; rel_ms: number | null; payload: string };
  const pages = keyedPages(
    (after) =>
      db.$client<Row[]>`
        select seq, rel_ms, payload::text as payload from trial_events
        where trial_id = ${trialId} and seq > ${(after?.[0] as number | undefined) ?? afterSeq}
        order by seq limit ${LOG_PAGE}`,
    (row) => [row.seq],
    LOG_PAGE,
  );
  let opening = "[";
  for await (const page of pages) {
    yield opening + page.map((r) => withPlace(r.payload, r.seq, r.rel_ms)).join(",");
    opening = ",";
  }
  yield opening === "[" ? "[]" : "]";
}

/** A payload's JSON object text with the event's seq and time since t0 as its last members (as toTrialEvent). */
export function withPlace(payload: string, seq: number, relMs: number | null): string {
  const place = `"seq":${seq},"relMs":${relMs}`;
  return payload.trimEnd() === "{}" ? `{${place}}` : `${payload.slice(0, payload.lastIndexOf("}"))},${place}}`;
}

/** A trial's events page by page (see eventsSince and keyedPages): at most two pages are held. */
export function eventPages(db: Database, trialId: string, page: Page): AsyncGenerator<StoredEvent[]> {
  return keyedPages(
    (after) => eventsSince(db, trialId, (after?.[0] as number | undefined) ?? 0, page),
    (e) => [e.seq],
    page.limit,
  );
}

/** The seqs each request of the trial's wizard was answered with: what a request sent again is answered from. */
export async function answeredRequests(db: Database, trialId: string): Promise<Map<string, number[]>> {
  const rows = await db
    .select({ requestId: trialEvents.requestId, seq: trialEvents.seq })
    .from(trialEvents)
    .where(and(eq(trialEvents.trialId, trialId), isNotNull(trialEvents.requestId)))
    .orderBy(asc(trialEvents.seq));
  const answered = new Map<string, number[]>();
  for (const { requestId, seq } of rows) answered.set(requestId!, [...(answered.get(requestId!) ?? []), seq]);
  return answered;
}

/** Every event of several trials in one query, each trial's in order: what exports read a batch of trials with. */
export async function eventsOfTrials(db: Database, trialIds: string[]): Promise<Map<string, StoredEvent[]>> {
  if (!trialIds.length) return new Map();
  // The driver's read, as eventsSince's: the same five columns and the trial's.
  const rows = await db.$client<Array<LogRow & { trialId: string }>>`
    select trial_id as "trialId", seq, rel_ms, server_time, actor_id, payload from trial_events
    where trial_id = any(${trialIds}::text[]) order by trial_id, seq`;
  return byTrial(trialIds, rows, (row) => toStored(row, row.trialId));
}

/**
 * The same, as the engine folds them: without the server's time, the actor or
 * the columns copied out of the payload, which halves the read. What a study's
 * figures are folded from, a batch of trials at a time.
 */
export async function foldableEventsOfTrials(db: Database, trialIds: string[]): Promise<Map<string, TrialEvent[]>> {
  if (!trialIds.length) return byTrial(trialIds, [], toTrialEvent);
  const rows = await db
    .select({
      trialId: trialEvents.trialId,
      seq: trialEvents.seq,
      relMs: trialEvents.relMs,
      payload: trialEvents.payload,
    })
    .from(trialEvents)
    .where(inArray(trialEvents.trialId, trialIds))
    .orderBy(asc(trialEvents.trialId), asc(trialEvents.seq));
  return byTrial(trialIds, rows, toTrialEvent);
}

/** Rows read in trial order, grouped by trial: every trial asked for has its list, empty if it has no events. */
function byTrial<R extends { trialId: string }, E>(trialIds: string[], rows: R[], toEvent: (row: R) => E) {
  const grouped = new Map<string, E[]>(trialIds.map((id) => [id, []]));
  for (const row of rows) grouped.get(row.trialId)!.push(toEvent(row));
  return grouped;
}
