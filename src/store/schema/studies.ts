import { sql } from "drizzle-orm";
import {
  bigint,
  doublePrecision,
  index,
  jsonb,
  pgTable,
  primaryKey,
  text,
  timestamp,
  uniqueIndex,
} from "drizzle-orm/pg-core";
import { user } from "./auth";
import { createdAt, id } from "./columns";
// Only inside lazy references: the two schema files refer to each other.
import { experiments } from "./experiments";

export const studies = pgTable("studies", {
  id: id(),
  title: text("title").notNull(),
  description: text("description").notNull().default(""),
  status: text("status", { enum: ["draft", "active", "completed", "archived"] })
    .notNull()
    .default("draft"),
  // Study-level switches (e.g. consent gating, blinding), versioned by the app.
  settings: jsonb("settings").notNull().default(sql`'{}'::jsonb`),
  createdBy: text("created_by").references(() => user.id, { onDelete: "set null" }),
  createdAt: createdAt(),
  updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
});

export const studyMembers = pgTable(
  "study_members",
  {
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    userId: text("user_id")
      .notNull()
      .references(() => user.id, { onDelete: "cascade" }),
    role: text("role", { enum: ["owner", "researcher", "wizard", "observer"] }).notNull(),
    addedAt: createdAt(),
  },
  (t) => [primaryKey({ columns: [t.studyId, t.userId] }), index("study_members_user_idx").on(t.userId)],
);

// A study's conditions, each bound to an experiment (and so to a robot).
export const conditions = pgTable(
  "conditions",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    name: text("name").notNull(),
    description: text("description").notNull().default(""),
    experimentId: text("experiment_id")
      .notNull()
      .references(() => experiments.id, { onDelete: "restrict" }),
    createdAt: createdAt(),
  },
  (t) => [
    uniqueIndex("conditions_study_name_idx").on(t.studyId, t.name),
    index("conditions_experiment_idx").on(t.experimentId),
  ],
);

export const participants = pgTable(
  "participants",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    code: text("code").notNull(),
    consentStatus: text("consent_status", { enum: ["pending", "given", "declined", "withdrawn"] })
      .notNull()
      .default("pending"),
    consentDate: timestamp("consent_date", { withTimezone: true }),
    // Which version of the study's consent document the participant agreed to.
    consentVersion: text("consent_version"),
    notes: text("notes").notNull().default(""),
    // Answers to the demographic fields the study defines (its settings), by field key.
    demographics: jsonb("demographics").notNull().default(sql`'{}'::jsonb`),
    // The server's assignment: which condition (or, within-subject, which order), made when and from what.
    conditionId: text("condition_id").references(() => conditions.id, { onDelete: "set null" }),
    conditionOrder: jsonb("condition_order"),
    assignment: jsonb("assignment"),
    createdAt: createdAt(),
  },
  (t) => [
    uniqueIndex("participants_study_code_idx").on(t.studyId, t.code),
    index("participants_condition_idx").on(t.conditionId),
  ],
);

// Who changed what, for administrative changes (members, roles, users, plugins).
export const auditLog = pgTable(
  "audit_log",
  {
    id: id(),
    at: timestamp("at", { withTimezone: true }).notNull().defaultNow(),
    actorId: text("actor_id").references(() => user.id, { onDelete: "set null" }),
    studyId: text("study_id").references(() => studies.id, { onDelete: "cascade" }),
    action: text("action").notNull(),
    target: text("target").notNull(),
    details: jsonb("details").notNull().default(sql`'{}'::jsonb`),
  },
  (t) => [index("audit_log_study_idx").on(t.studyId, t.at)],
);

// Sounds a study's experiments play ("Play audio"): the bytes live in media
// storage under storage_key; sha256 is what a published version pins.
export const studyAudio = pgTable(
  "study_audio",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    name: text("name").notNull(),
    mimeType: text("mime_type").notNull(),
    sizeBytes: bigint("size_bytes", { mode: "number" }).notNull(),
    sha256: text("sha256").notNull(),
    // Read from the file's own header when it says; null when it does not.
    durationMs: doublePrecision("duration_ms"),
    storageKey: text("storage_key").notNull(),
    uploadedBy: text("uploaded_by").references(() => user.id, { onDelete: "set null" }),
    createdAt: createdAt(),
  },
  (t) => [index("study_audio_study_idx").on(t.studyId)],
);
