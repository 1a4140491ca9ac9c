// Questionnaires of a study, their published versions, the one-time links a
// participant fills them in through, and the answers (kept as a draft until
// submitted, so a reload never loses them).
import { sql } from "drizzle-orm";
import { index, integer, jsonb, pgTable, text, timestamp, uniqueIndex } from "drizzle-orm/pg-core";
import { user } from "./auth";
import { createdAt, id } from "./columns";
import { participants, studies } from "./studies";
import { trials } from "./trials";

export const questionnaires = pgTable(
  "questionnaires",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    name: text("name").notNull(),
    draft: jsonb("draft").notNull(),
    /** When its sessions use it: before the trial, after it, or not attached. */
    timing: text("timing", { enum: ["before", "after", "none"] })
      .notNull()
      .default("none"),
    createdAt: createdAt(),
    updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [index("questionnaires_study_idx").on(t.studyId)],
);

export const questionnaireVersions = pgTable(
  "questionnaire_versions",
  {
    id: id(),
    questionnaireId: text("questionnaire_id")
      .notNull()
      .references(() => questionnaires.id, { onDelete: "restrict" }),
    version: integer("version").notNull(),
    definition: jsonb("definition").notNull(),
    hash: text("hash").notNull(),
    publishedBy: text("published_by").references(() => user.id, { onDelete: "set null" }),
    publishedAt: timestamp("published_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [uniqueIndex("questionnaire_versions_idx").on(t.questionnaireId, t.version)],
);

export const questionnaireLinks = pgTable(
  "questionnaire_links",
  {
    id: id(),
    /** SHA-256 of the token: the database never holds a usable link. */
    tokenHash: text("token_hash").notNull().unique(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    versionId: text("version_id")
      .notNull()
      .references(() => questionnaireVersions.id, { onDelete: "restrict" }),
    participantId: text("participant_id")
      .notNull()
      .references(() => participants.id, { onDelete: "restrict" }),
    trialId: text("trial_id").references(() => trials.id, { onDelete: "set null" }),
    expiresAt: timestamp("expires_at", { withTimezone: true }).notNull(),
    usedAt: timestamp("used_at", { withTimezone: true }),
    createdBy: text("created_by").references(() => user.id, { onDelete: "set null" }),
    createdAt: createdAt(),
  },
  (t) => [
    index("questionnaire_links_study_idx").on(t.studyId),
    index("questionnaire_links_version_idx").on(t.versionId),
    index("questionnaire_links_participant_idx").on(t.participantId),
    index("questionnaire_links_trial_idx").on(t.trialId),
  ],
);

export const questionnaireResponses = pgTable("questionnaire_responses", {
  id: id(),
  linkId: text("link_id")
    .notNull()
    .unique()
    .references(() => questionnaireLinks.id, { onDelete: "cascade" }),
  answers: jsonb("answers").notNull().default(sql`'{}'::jsonb`),
  status: text("status", { enum: ["draft", "submitted"] })
    .notNull()
    .default("draft"),
  score: jsonb("score"),
  submittedAt: timestamp("submitted_at", { withTimezone: true }),
  updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
});
