// Exports of a trial: tidy CSV of its events (one row per event) and the full
// record as JSON. Pure string builders; the server only streams them.
import type { ProtocolSnapshot } from "@/core/protocol/snapshot";
import { csvDocument } from "@/core/csv/csv";

export const TRIAL_RECORD_SCHEMA_VERSION = 1;

export interface ExportEvent {
  seq: number;
  type: string;
  relMs: number | null;
  serverTime: string | Date;
  actorId: string | null;
  stepId?: string | null;
  actionId?: string;
  actionType?: string;
  deviation?: string;
  [more: string]: unknown;
}

export const EVENT_COLUMNS = ["trial_id", "seq", "type", "step_id", "action_id", "action_type", "deviation", "rel_ms", "server_time", "actor_id", "payload"] as const;

export function eventsCsv(trialId: string, events: ExportEvent[]): string {
  const rows = events.map((e) => [
    trialId,
    e.seq,
    e.type,
    e.stepId ?? "",
    e.actionId ?? "",
    e.actionType ?? "",
    e.deviation ?? "",
    e.relMs ?? "",
    e.serverTime instanceof Date ? e.serverTime.toISOString() : e.serverTime,
    e.actorId ?? "",
    JSON.stringify(e),
  ]);
  return csvDocument(EVENT_COLUMNS, rows);
}

export interface TrialRecord {
  schemaVersion: number;
  trial: Record<string, unknown>;
  protocol: ProtocolSnapshot;
  events: ExportEvent[];
  annotations: Array<{ relMs: number; label: string; note: string; authorName: string | null }>;
  /** Submitted questionnaires of the trial, each with the version shown, the answers and the score. */
  questionnaires: unknown[];
  /** Recordings of the trial: where to fetch them, and their offset from t0 (ms). */
  recordings: unknown[];
}

export function trialRecordJson(record: Omit<TrialRecord, "schemaVersion">): string {
  return JSON.stringify({ schemaVersion: TRIAL_RECORD_SCHEMA_VERSION, ...record }, null, 2);
}
