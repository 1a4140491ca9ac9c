// The analysis API (/api/v1), declared once: each endpoint's path, what it
// returns and its columns. The route handlers, the OpenAPI description and
// the test that every route is described all read this list.
import { CODE_COLUMNS } from "@/core/coding/export";
import { ANSWER_COLUMNS } from "@/core/questionnaires/export";
import { EVENT_COLUMNS, SAMPLE_COLUMNS } from "./exports";

export const API_BASE = "/api/v1";

export const STUDY_COLUMNS = ["study_id", "title", "status", "role", "results_hidden"] as const;
export const TRIAL_COLUMNS = [
  "trial_id",
  "experiment",
  "version",
  "participant",
  "condition",
  "wizard",
  "status",
  "started_at",
  "ended_at",
  "duration_ms",
] as const;
export const ANNOTATION_COLUMNS = ["trial_id", "rel_ms", "label", "note", "author"] as const;

export interface Endpoint {
  /** Below API_BASE, with OpenAPI's {parameter} for the id of the row it reads. */
  path: string;
  summary: string;
  description: string;
  columns: readonly string[];
}

const STUDY_DATA = "The study's trials (rehearsals and participants who withdrew left out, as in the study's archive).";

export const ENDPOINTS = {
  studies: {
    path: "/studies",
    summary: "The studies this token may read",
    description:
      "Each study the token was made for and its owner is still a member of. results_hidden is true while the study's blinding hides results: its data endpoints answer 403 until it is completed.",
    columns: STUDY_COLUMNS,
  },
  trials: {
    path: "/studies/{studyId}/trials",
    summary: "The study's trials",
    description: `One row per trial: experiment and version, participant and condition, wizard, status and times. ${STUDY_DATA}`,
    columns: TRIAL_COLUMNS,
  },
  events: {
    path: "/studies/{studyId}/events",
    summary: "Every event of the study's trials",
    description: `One row per event, as in a trial's events CSV: sequence, time since the trial started, type, step and action with their names, deviation, and the whole event as JSON in payload. ${STUDY_DATA}`,
    columns: EVENT_COLUMNS,
  },
  samples: {
    path: "/studies/{studyId}/samples",
    summary: "Robot state recorded during the study's trials",
    description: `One row per sample (joint states and other robot topics): topic, time since the trial started (ms), the message as JSON. ${STUDY_DATA}`,
    columns: SAMPLE_COLUMNS,
  },
  answers: {
    path: "/studies/{studyId}/answers",
    summary: "Questionnaire answers",
    description:
      "Every submitted answer: one row per participant × item in the order shown, then a row per score (item_id score or score.<subscale>). Participants who withdrew are left out.",
    columns: ANSWER_COLUMNS,
  },
  annotations: {
    path: "/studies/{studyId}/annotations",
    summary: "Observers' annotations",
    description: `One row per annotation made during or after a trial, on the trial's clock. ${STUDY_DATA}`,
    columns: ANNOTATION_COLUMNS,
  },
  codes: {
    path: "/studies/{studyId}/codes",
    summary: "Observers' codes",
    description: `One row per code event of a coding scheme: its observer, the scheme and its version, set and code by name, point or state, start and end on the trial's clock (ms; a point event or a state still held has no end), modifiers joined with "; ". ${STUDY_DATA}`,
    columns: CODE_COLUMNS,
  },
  trialEvents: {
    path: "/trials/{trialId}/events",
    summary: "The events of one trial",
    description: "The same columns as the study's events, for one trial (a rehearsal included).",
    columns: EVENT_COLUMNS,
  },
} as const satisfies Record<string, Endpoint>;

export type EndpointName = keyof typeof ENDPOINTS;

/** Where the description itself is served; described in it too. */
export const OPENAPI_PATH = "/openapi.json";

/** The {parameters} of a path, in order. */
export const pathParameters = (path: string) => [...path.matchAll(/\{(\w+)\}/g)].map((m) => m[1]!);

export type Format = "csv" | "json";

/**
 * ?format= decides; without it, an Accept header that asks for JSON (and not
 * CSV) does; otherwise CSV. Anything else in ?format= is a mistake to report.
 */
export function chooseFormat(format: string | null, accept: string | null): Format | { error: string } {
  if (format === "csv" || format === "json") return format;
  if (format !== null) return { error: `Please correct: format: must be csv or json (not “${format}”)` };
  const wants = accept?.toLowerCase() ?? "";
  return wants.includes("application/json") && !wants.includes("text/csv") ? "json" : "csv";
}
