// What each column of the tidy tables holds, declared once: its type, unit
// and allowed values. The OpenAPI description types the analysis API's JSON
// from it, and the study zip's codebook.csv is written from it, so a paper's
// reader needs nothing else to read the data.
import { STUDY_ROLES } from "@/core/access/policy";
import type { CODE_COLUMNS } from "@/core/coding/export";
import type { ANSWER_COLUMNS } from "@/core/questionnaires/export";
import { STUDY_STATUSES } from "@/core/studies/status";
import { DEVIATION_KINDS, TRIAL_STATUSES } from "@/core/trial/types";
import type { ANNOTATION_COLUMNS, STUDY_COLUMNS, TRIAL_COLUMNS } from "./api";
import type { EVENT_COLUMNS, SAMPLE_COLUMNS } from "./exports";

export interface Column {
  /** "json" is text holding a JSON value; "date-time" an ISO 8601 time in UTC. */
  type: "text" | "integer" | "number" | "boolean" | "date-time" | "json" | "number or text";
  /** Empty (null in JSON) where the row has no value. */
  optional?: boolean;
  unit?: string;
  values?: readonly string[];
  description: string;
}

const TRIAL_ID: Column = { type: "text", description: "The trial's id." };
const REL_MS: Column = {
  type: "integer",
  unit: "ms",
  description: "Time since the trial started (its t0), on the trial's clock.",
};
const PARTICIPANT: Column = { type: "text", description: "The participant's code." };
const CONDITION: Column = {
  type: "text",
  optional: true,
  description: "The participant's condition (empty if the study has none or they are not assigned).",
};
const WIZARD: Column = { type: "text", optional: true, description: "The name of the wizard who ran the trial." };

type Columns<C extends readonly string[]> = Record<C[number], Column>;

const STUDY: Columns<typeof STUDY_COLUMNS> = {
  study_id: { type: "text", description: "The study's id." },
  title: { type: "text", description: "The study's title." },
  status: { type: "text", values: STUDY_STATUSES, description: "The study's status." },
  role: { type: "text", values: STUDY_ROLES, description: "The token owner's role in the study." },
  results_hidden: {
    type: "boolean",
    description: "True while the study's blinding hides results: its data tables are refused until it is completed.",
  },
};

const TRIAL: Columns<typeof TRIAL_COLUMNS> = {
  trial_id: TRIAL_ID,
  experiment: { type: "text", description: "The experiment's name." },
  version: { type: "integer", optional: true, description: "The published version of the experiment run." },
  participant: PARTICIPANT,
  condition: CONDITION,
  wizard: WIZARD,
  status: {
    type: "text",
    values: TRIAL_STATUSES,
    description: "The trial's status.",
  },
  started_at: { type: "date-time", optional: true, description: "When the trial started (its t0), UTC." },
  ended_at: { type: "date-time", optional: true, description: "When the trial ended, UTC." },
  duration_ms: { type: "integer", optional: true, unit: "ms", description: "From start to end." },
};

const EVENT: Columns<typeof EVENT_COLUMNS> = {
  trial_id: TRIAL_ID,
  wizard: WIZARD,
  created_by: { type: "text", optional: true, description: "The name of the person who created the trial." },
  seq: { type: "integer", description: "The event's place in its trial's log, from 1." },
  type: { type: "text", description: "What happened (trial.started, action.dispatched…: docs/analysis.md)." },
  step_id: { type: "text", optional: true, description: "The id of the step the event is about." },
  action_id: { type: "text", optional: true, description: "The id of the action the event is about." },
  action_type: { type: "text", optional: true, description: "The action's type, on its request." },
  step_name: { type: "text", optional: true, description: "The step's name." },
  action_name: { type: "text", optional: true, description: "The action's name." },
  variant: {
    type: "text",
    optional: true,
    description:
      "The condition whose variant of the action ran (the condition's name); empty for the action every condition shares.",
  },
  answer: {
    type: "text",
    optional: true,
    description: "The participant's answer, as the wizard recorded it (its label), on an answer.recorded row.",
  },
  sensed: {
    type: "text",
    optional: true,
    description:
      "What the robot sensed (the id of its plugin's event, e.g. head_touched), on a robot.sensed row; its time and message are in the payload.",
  },
  deviation: {
    type: "text",
    optional: true,
    values: DEVIATION_KINDS,
    description: "How the event departs from the protocol, if it does.",
  },
  rel_ms: { ...REL_MS, optional: true, description: `${REL_MS.description} Empty before the start.` },
  server_time: { type: "date-time", description: "When the server logged the event, UTC." },
  actor_id: { type: "text", optional: true, description: "The id of the person who caused the event." },
  payload: {
    type: "json",
    description: "The whole event; a dispatched action's detail.sent holds what the robot was sent.",
  },
};

const SAMPLE: Columns<typeof SAMPLE_COLUMNS> = {
  trial_id: TRIAL_ID,
  topic: { type: "text", description: "The robot topic the sample came on." },
  rel_ms: REL_MS,
  data: { type: "json", description: "The message as the robot sent it." },
};

const ANSWER: Columns<typeof ANSWER_COLUMNS> = {
  participant: PARTICIPANT,
  condition: CONDITION,
  trial_id: { ...TRIAL_ID, optional: true, description: "The trial the questionnaire was given with, if any." },
  questionnaire: { type: "text", description: "The questionnaire's name in the study." },
  instrument: {
    type: "text",
    optional: true,
    description: "The standard instrument it is (its published name), empty for the study's own questionnaires.",
  },
  version: { type: "integer", description: "The version of the questionnaire shown." },
  measure: {
    type: "text",
    values: ["answer", "score"],
    description: "An item's answer, or a score computed the instrument's published way.",
  },
  item_id: { type: "text", optional: true, description: "The item's id (empty on a score)." },
  item: { type: "text", description: "The item's text, or the score's published name." },
  subscale: {
    type: "text",
    optional: true,
    description: "The published sub-scale the item belongs to, or the score is of.",
  },
  reverse_scored: {
    type: "boolean",
    optional: true,
    description: "Whether the instrument scores the item reversed (empty outside an instrument, and on a score).",
  },
  answer: {
    type: "number or text",
    optional: true,
    description: 'The answer as given (choices joined with "; "), or the score.',
  },
};

const ANNOTATION: Columns<typeof ANNOTATION_COLUMNS> = {
  trial_id: TRIAL_ID,
  rel_ms: REL_MS,
  label: { type: "text", description: "The annotation's label." },
  note: { type: "text", optional: true, description: "The observer's note." },
  author: { type: "text", optional: true, description: "Who made it." },
};

const CODE: Columns<typeof CODE_COLUMNS> = {
  trial_id: TRIAL_ID,
  observer: { type: "text", description: "The observer who coded." },
  scheme: { type: "text", description: "The coding scheme's name." },
  scheme_version: { type: "integer", description: "The version of the scheme coded with." },
  set: { type: "text", description: "The code set's name." },
  code: { type: "text", description: "The code's name." },
  kind: { type: "text", values: ["point", "state"], description: "A point in time, or a state held." },
  start_ms: { ...REL_MS, description: "When the code starts, on the trial's clock." },
  end_ms: { ...REL_MS, optional: true, description: "When a state ends (empty for a point, or a state still held)." },
  modifiers: { type: "text", optional: true, description: 'Its modifiers, joined with "; ".' },
};

/** Every table's columns, by the tables' names in the analysis API. */
export const TABLE_COLUMNS = {
  studies: STUDY,
  trials: TRIAL,
  events: EVENT,
  samples: SAMPLE,
  answers: ANSWER,
  annotations: ANNOTATION,
  codes: CODE,
} as const;

/** A column's JSON Schema, as the analysis API's JSON gives it. */
export function columnSchema(column: Column): Record<string, unknown> {
  const base =
    column.type === "date-time"
      ? { type: "string", format: "date-time" }
      : column.type === "json"
        ? { type: "string", contentMediaType: "application/json" }
        : column.type === "number or text"
          ? { type: ["number", "string"] }
          : { type: column.type === "text" ? "string" : column.type };
  const typed = column.optional ? { ...base, type: [...[base.type].flat(), "null"] } : base;
  return {
    ...typed,
    ...(column.values ? { enum: [...column.values, ...(column.optional ? [null] : [])] } : {}),
    description: column.unit ? `${column.description} (${column.unit})` : column.description,
  };
}
