// A study's coding schemes, their published versions, and the code events
// observers mark in trials: each event is its observer's own (their tier),
// timed on the trial's clock, and points at the exact scheme version used.
import { doublePrecision, index, integer, jsonb, pgTable, text, timestamp, uniqueIndex } from "drizzle-orm/pg-core";
import { user } from "./auth";
import { createdAt, id } from "./columns";
import { studies } from "./studies";
import { trials } from "./trials";

export const codingSchemes = pgTable(
  "coding_schemes",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    name: text("name").notNull(),
    draft: jsonb("draft").notNull(),
    createdAt: createdAt(),
    updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [index("coding_schemes_study_idx").on(t.studyId)],
);

export const codingSchemeVersions = pgTable(
  "coding_scheme_versions",
  {
    id: id(),
    schemeId: text("scheme_id")
      .notNull()
      // A version goes only with its study (there is no deleting a scheme): then its codes go too.
      .references(() => codingSchemes.id, { onDelete: "cascade" }),
    version: integer("version").notNull(),
    definition: jsonb("definition").notNull(),
    hash: text("hash").notNull(),
    publishedBy: text("published_by").references(() => user.id, { onDelete: "set null" }),
    publishedAt: timestamp("published_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [uniqueIndex("coding_scheme_versions_idx").on(t.schemeId, t.version)],
);

export const codeEvents = pgTable(
  "code_events",
  {
    id: id(),
    trialId: text("trial_id")
      .notNull()
      .references(() => trials.id, { onDelete: "cascade" }),
    observerId: text("observer_id").references(() => user.id, { onDelete: "set null" }),
    versionId: text("version_id")
      .notNull()
      .references(() => codingSchemeVersions.id, { onDelete: "cascade" }),
    setId: text("set_id").notNull(),
    codeId: text("code_id").notNull(),
    kind: text("kind", { enum: ["point", "state"] }).notNull(),
    /** Milliseconds since the trial's t0; a state's end is null while it still holds. */
    startMs: doublePrecision("start_ms").notNull(),
    endMs: doublePrecision("end_ms"),
    modifiers: jsonb("modifiers").$type<string[]>().notNull().default([]),
    createdAt: createdAt(),
    updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [
    index("code_events_trial_idx").on(t.trialId, t.startMs),
    // An observer's tier, and the codes of a scheme version (its deletion with the study looks them up).
    index("code_events_observer_idx").on(t.observerId),
    index("code_events_version_idx").on(t.versionId),
  ],
);
