import { sql } from "drizzle-orm";
import {
  bigint,
  bigserial,
  boolean,
  doublePrecision,
  index,
  integer,
  json,
  jsonb,
  pgTable,
  primaryKey,
  text,
  timestamp,
  uniqueIndex,
} from "drizzle-orm/pg-core";
import { user } from "./auth";
import { experimentVersions, experiments } from "./experiments";
import { createdAt, id, snapshot } from "./columns";
import { participants, studies } from "./studies";
import { robots } from "./robots";
import { LIVE_STATUSES, TRIAL_STATUSES } from "../../core/trial/types";

export const trials = pgTable(
  "trials",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    experimentId: text("experiment_id")
      .notNull()
      .references(() => experiments.id, { onDelete: "cascade" }),
    // Null only for a rehearsal, which runs the snapshot of the draft below.
    versionId: text("version_id").references(() => experimentVersions.id, { onDelete: "restrict" }),
    rehearsalSnapshot: snapshot("rehearsal_snapshot"),
    participantId: text("participant_id").references(() => participants.id, { onDelete: "restrict" }),
    wizardId: text("wizard_id").references(() => user.id, { onDelete: "set null" }),
    status: text("status", { enum: TRIAL_STATUSES }).notNull().default("scheduled"),
    isRehearsal: boolean("is_rehearsal").notNull().default(false),
    // The registered robot the trial drives: chosen when it is created or first opened, changeable until it starts.
    assignedRobotId: text("assigned_robot_id").references(() => robots.id, { onDelete: "set null" }),
    t0: timestamp("t0", { withTimezone: true }),
    // Counts the runtime processes that took the trial (its fencing token): an owner's append carries the
    // count it took it with, and is refused once another has taken the trial since.
    ownerEpoch: integer("owner_epoch").notNull().default(0),
    endedAt: timestamp("ended_at", { withTimezone: true }),
    createdBy: text("created_by").references(() => user.id, { onDelete: "set null" }),
    createdAt: createdAt(),
  },
  (t) => [
    index("trials_study_idx").on(t.studyId, t.createdAt),
    index("trials_experiment_idx").on(t.experimentId),
    index("trials_version_idx").on(t.versionId),
    index("trials_participant_idx").on(t.participantId),
    index("trials_wizard_idx").on(t.wizardId),
    index("trials_robot_idx").on(t.assignedRobotId),
    // One robot is never driven by two live trials, whichever runtime process runs them.
    uniqueIndex("trials_live_robot_idx")
      .on(t.assignedRobotId)
      .where(sql`${t.status} in ${sql.raw(`(${LIVE_STATUSES.map((s) => `'${s}'`).join(", ")})`)}`),
  ],
);

// The append-only log a trial's state is folded from.
export const trialEvents = pgTable(
  "trial_events",
  {
    trialId: text("trial_id")
      .notNull()
      .references(() => trials.id, { onDelete: "cascade" }),
    seq: integer("seq").notNull(),
    type: text("type").notNull(),
    serverTime: timestamp("server_time", { withTimezone: true, precision: 6 }).notNull(),
    // Milliseconds since the trial's t0; null for events before the start.
    relMs: doublePrecision("rel_ms"),
    actorId: text("actor_id").references(() => user.id, { onDelete: "set null" }),
    stepId: text("step_id"),
    actionId: text("action_id"),
    payload: jsonb("payload").notNull().default(sql`'{}'::jsonb`),
    deviation: boolean("deviation").notNull().default(false),
    // The wizard's request these events answer (its idempotency key): a command sent again after a
    // dropped connection is answered from the log, never carried out twice.
    requestId: text("request_id"),
  },
  (t) => [primaryKey({ columns: [t.trialId, t.seq] })],
);

// High-rate robot data (joint states, battery…), written in batches.
export const trialSamples = pgTable(
  "trial_samples",
  {
    id: bigserial("id", { mode: "number" }).primaryKey(),
    trialId: text("trial_id")
      .notNull()
      .references(() => trials.id, { onDelete: "cascade" }),
    topic: text("topic").notNull(),
    relMs: doublePrecision("rel_ms").notNull(),
    data: jsonb("data").notNull(),
  },
  (t) => [
    index("trial_samples_trial_idx").on(t.trialId, t.topic, t.relMs),
    // The exports' order (a trial's samples in time, ties as written): a download reads a page where the last ended.
    index("trial_samples_order_idx").on(t.trialId, t.relMs, t.id),
  ],
);

export const annotations = pgTable(
  "annotations",
  {
    id: id(),
    trialId: text("trial_id")
      .notNull()
      .references(() => trials.id, { onDelete: "cascade" }),
    authorId: text("author_id").references(() => user.id, { onDelete: "set null" }),
    relMs: doublePrecision("rel_ms").notNull(),
    label: text("label").notNull(),
    note: text("note").notNull().default(""),
    createdAt: createdAt(),
    updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [index("annotations_trial_idx").on(t.trialId, t.relMs)],
);

export const mediaRecordings = pgTable(
  "media_recordings",
  {
    id: id(),
    trialId: text("trial_id")
      .notNull()
      .references(() => trials.id, { onDelete: "cascade" }),
    kind: text("kind", { enum: ["video", "audio"] }).notNull(),
    storageKey: text("storage_key").notNull(),
    mimeType: text("mime_type").notNull(),
    sizeBytes: bigint("size_bytes", { mode: "number" }).notNull().default(0),
    status: text("status", { enum: ["recording", "complete", "failed"] })
      .notNull()
      .default("recording"),
    // Recording start minus the trial's t0, as measured.
    offsetMs: doublePrecision("offset_ms"),
    durationMs: doublePrecision("duration_ms"),
    chunkCount: integer("chunk_count").notNull().default(0),
    createdAt: createdAt(),
    // When its last part arrived: a recorder that has sent nothing for a while has gone (its page closed).
    lastPartAt: timestamp("last_part_at", { withTimezone: true }),
    // Finished by the server from the parts it held, because the page recording it went away.
    cutOff: boolean("cut_off").notNull().default(false),
    finishedAt: timestamp("finished_at", { withTimezone: true }),
  },
  (t) => [
    index("media_recordings_trial_idx").on(t.trialId),
    // The server's look for recordings left open: only those still open.
    index("media_recordings_open_idx").on(t.createdAt).where(sql`${t.status} = 'recording'`),
  ],
);

// Each ended trial's figures for the study's tables, folded once from its log (src/server/studies/summary.ts).
// A copy stands while its figures version, the trial's protocol version and its last seq are still the trial's:
// a robot's late report after the end, or a new way of computing, makes it again.
export const trialFigures = pgTable("trial_figures", {
  trialId: text("trial_id")
    .primaryKey()
    .references(() => trials.id, { onDelete: "cascade" }),
  figuresVersion: integer("figures_version").notNull(),
  versionId: text("version_id").notNull(),
  lastSeq: bigint("last_seq", { mode: "number" }).notNull(),
  // json, not jsonb: kept as written, so the deviation kinds come back in the order the trial met them.
  figures: json("figures").notNull(),
  computedAt: timestamp("computed_at", { withTimezone: true }).notNull().defaultNow(),
});
