// Exports of a trial: tidy CSV of its events (one row per event) and the full
// record as JSON. Pure string builders; the server only streams them. Both
// name the step and the action an event is about (see names.ts), so a reader
// never has to look ids up in the protocol.
import type { ProtocolSnapshot } from "@/core/protocol/snapshot";
import { csvDocument, type CsvValue } from "@/core/csv/csv";
import type { StoredEvent } from "@/core/trial";
import { answerOf } from "./answers";
import type { TrialNames } from "./names";

// 2: the protocol is snapshot schema 2 (robotId; steps say where they lead), the version names its robotId.
// 3: observers' codes (`codes`, one record per code event as in the codes CSV).
export const TRIAL_RECORD_SCHEMA_VERSION = 3;

export const EVENT_COLUMNS = [
  "trial_id",
  "wizard",
  "created_by",
  "seq",
  "type",
  "step_id",
  "action_id",
  "action_type",
  "step_name",
  "action_name",
  "variant",
  "answer",
  "sensed",
  "deviation",
  "rel_ms",
  "server_time",
  "actor_id",
  "payload",
] as const;

/** Who ran the trial (its wizard) and who created it, by name: two people, often not the same. */
export interface TrialPeople {
  wizard: string | null;
  createdBy: string | null;
}

export function eventsCsv(trialId: string, events: StoredEvent[], people: TrialPeople, names: TrialNames): string {
  return csvDocument(EVENT_COLUMNS, eventRows(trialId, events, people, names));
}

/** The cells of eventsCsv, one row per event: the analysis API returns them as CSV or JSON. */
export function eventRows(
  trialId: string,
  events: StoredEvent[],
  people: TrialPeople,
  names: TrialNames,
): CsvValue[][] {
  return events.map((e) => {
    // Columns for the fields some kinds of event have; the payload column holds all of it.
    const { stepId, actionId, actionType } = e as { stepId?: string | null; actionId?: string; actionType?: string };
    const { stepName, actionName, variant } = names.of(e);
    // An empty cell is null: empty in the CSV, null in the analysis API's JSON (never "" for a number).
    return [
      trialId,
      people.wizard,
      people.createdBy,
      e.seq,
      e.type,
      stepId ?? null,
      actionId ?? null,
      actionType ?? null,
      stepName ?? null,
      actionName ?? null,
      variant ?? null,
      answerOf(e) ?? null,
      e.type === "robot.sensed" ? e.event : null,
      e.deviation ?? null,
      e.relMs,
      e.serverTime.toISOString(),
      e.actorId,
      JSON.stringify(e),
    ];
  });
}

/** The samples CSV's columns, the analysis API's samples table's too. (Here, not in api.ts, which imports
 * this file: a cycle either way round would leave one of them undefined when the other loads first.) */
export const SAMPLE_COLUMNS = ["trial_id", "topic", "rel_ms", "data"] as const;

/** A robot state sample as logged: its topic, when (ms from t0) and the message as the robot sent it. */
export interface Sample {
  topic: string;
  relMs: number;
  data: unknown;
}

/** A trial's robot state samples as tidy CSV, in the analysis API's samples columns: one row per sample, the message as JSON. */
export function samplesCsv(trialId: string, samples: Sample[]): string {
  return csvDocument(
    SAMPLE_COLUMNS,
    samples.map((s) => [trialId, s.topic, s.relMs, JSON.stringify(s.data)]),
  );
}

export interface TrialRecord {
  schemaVersion: number;
  trial: Record<string, unknown>;
  protocol: ProtocolSnapshot;
  /** Each with `stepName` and `actionName` when it is about a step or an action. */
  events: Array<StoredEvent & { stepName?: string; actionName?: string }>;
  annotations: Array<{ relMs: number; label: string; note: string; authorName: string | null }>;
  /** Submitted questionnaires of the trial, each with the version shown, the answers and the score. */
  questionnaires: unknown[];
  /** Recordings of the trial: where to fetch them, and their offset from t0 (ms). */
  recordings: unknown[];
  /** The robot's state samples (joint states, battery…) in time order. */
  samples: Sample[];
  /** Observers' code events, one row each as in the codes CSV (CODE_COLUMNS). */
  codes: Array<Record<string, unknown>>;
}

/** The record's events as its JSON holds them: each with the names of its step and action. */
export function namedEvents(events: StoredEvent[], names: TrialNames) {
  return events.map((e) => ({ ...e, ...names.of(e) }));
}

/**
 * A JSON array written a batch of items at a time, byte for byte as
 * JSON.stringify(…, null, 2) writes it as the value of a key at `depth`
 * (1: a key of the document's top object): a record too large to hold goes
 * out as it is read. Literal newlines only ever occur between tokens (a
 * string's are escaped), so indenting an item is replacing them.
 */
function jsonArrayWriter(depth: number) {
  const pad = `\n${"  ".repeat(depth + 1)}`;
  let written = 0;
  return {
    items: (items: unknown[]) =>
      items
        .map((item) => `${written++ ? "," : "["}${pad}${JSON.stringify(item, null, 2).replaceAll("\n", pad)}`)
        .join(""),
    end: () => (written ? `\n${"  ".repeat(depth)}]` : "[]"),
  };
}

/** A list given a batch of items at a time: a part of a record too large to hold, read as it is written. */
export type Batches<T> = AsyncIterable<T[]>;

const isBatches = (value: unknown): value is Batches<unknown> =>
  typeof value === "object" && value !== null && Symbol.asyncIterator in value;

/**
 * A JSON object written a piece at a time, byte for byte as
 * JSON.stringify(object, null, 2) writes it whole: a value given as Batches is
 * written as an array a batch at a time (the rest whole, indented as a key of
 * the top object). Memory holds one batch and what lies between two lists.
 */
export async function* jsonPieces(object: Record<string, unknown>): AsyncGenerator<string> {
  let text = "";
  let keys = 0;
  for (const [key, value] of Object.entries(object)) {
    const whole = isBatches(value) ? undefined : JSON.stringify(value, null, 2);
    // JSON.stringify leaves out a key whose value it cannot write (undefined, a function).
    if (!isBatches(value) && whole === undefined) continue;
    text += `${keys++ ? "," : "{"}\n  ${JSON.stringify(key)}: `;
    if (!isBatches(value)) {
      text += whole!.replaceAll("\n", "\n  ");
      continue;
    }
    // What comes before the list goes out before its first batch is read: the first byte waits for no read.
    yield text;
    text = "";
    const array = jsonArrayWriter(1);
    for await (const batch of value) {
      text += array.items(batch);
      if (text) yield text;
      text = "";
    }
    text += array.end();
  }
  yield keys ? `${text}\n}` : "{}";
}

type Whole = Omit<TrialRecord, "schemaVersion">;

/** The record's lists given whole or a batch at a time (events named, codes as records, as the record holds them). */
export type StreamedRecord = { [K in keyof Whole]: Whole[K] extends (infer I)[] ? Whole[K] | Batches<I> : Whole[K] };

/** The record's keys in the order its JSON lists them: the events after the protocol, as TrialRecord lists them. */
function inRecordOrder<R extends StreamedRecord>(record: R) {
  const { trial, protocol, events, annotations, questionnaires, recordings, samples, codes } = record;
  return {
    schemaVersion: TRIAL_RECORD_SCHEMA_VERSION,
    trial,
    protocol,
    events,
    annotations,
    questionnaires,
    recordings,
    samples,
    codes,
  };
}

/**
 * The trial record as JSON, a piece at a time: the same bytes as
 * trialRecordJson, its lists written as their batches are read.
 */
export function trialRecordPieces(record: StreamedRecord): AsyncGenerator<string> {
  return jsonPieces(inRecordOrder(record));
}

export function trialRecordJson(
  record: Omit<TrialRecord, "schemaVersion" | "events"> & { events: StoredEvent[] },
  names: TrialNames,
): string {
  return JSON.stringify(inRecordOrder({ ...record, events: namedEvents(record.events, names) }), null, 2);
}
