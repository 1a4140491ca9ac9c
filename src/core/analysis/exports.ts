// Exports of a trial: tidy CSV of its events (one row per event) and the full
// record as JSON. Pure string builders; the server only streams them. Both
// name the step and the action an event is about (see names.ts), so a reader
// never has to look ids up in the protocol.
import type { ProtocolSnapshot } from "@/core/protocol/snapshot";
import { csvDocument, type CsvValue } from "@/core/csv/csv";
import type { StoredEvent } from "@/core/trial";
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
    const { stepName, actionName } = names.of(e);
    return [
      trialId,
      people.wizard ?? "",
      people.createdBy ?? "",
      e.seq,
      e.type,
      stepId ?? "",
      actionId ?? "",
      actionType ?? "",
      stepName ?? "",
      actionName ?? "",
      e.deviation ?? "",
      e.relMs ?? "",
      e.serverTime.toISOString(),
      e.actorId ?? "",
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
export function jsonArrayWriter(depth: number) {
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

/**
 * The trial record's JSON around its events: the text before them and the
 * text after. The events go between as a jsonArrayWriter(1) writes them, so
 * the record can be written a batch of events at a time.
 */
export function trialRecordFrame(record: Omit<TrialRecord, "schemaVersion" | "events">) {
  // The events after the protocol, as TrialRecord lists them.
  const { trial, protocol, ...rest } = record;
  const whole = JSON.stringify(
    { schemaVersion: TRIAL_RECORD_SCHEMA_VERSION, trial, protocol, events: [], ...rest },
    null,
    2,
  );
  // A newline and two spaces before a quote start a key of the top object only (deeper keys are
  // indented further, a string's newlines are escaped), and its keys are unique.
  const key = '\n  "events": ';
  const at = whole.indexOf(`${key}[]`);
  return { before: whole.slice(0, at + key.length), after: whole.slice(at + key.length + 2) };
}

export function trialRecordJson(
  record: Omit<TrialRecord, "schemaVersion" | "events"> & { events: StoredEvent[] },
  names: TrialNames,
): string {
  const { events, ...rest } = record;
  const { before, after } = trialRecordFrame(rest);
  const array = jsonArrayWriter(1);
  return before + array.items(namedEvents(events, names)) + array.end() + after;
}
