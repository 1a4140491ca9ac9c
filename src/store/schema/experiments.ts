import { sql } from "drizzle-orm";
import { index, integer, jsonb, pgTable, text, timestamp, uniqueIndex } from "drizzle-orm/pg-core";
import type { ActionVariant, After, StepVariant, TimeLimit } from "../../core/protocol/document";
import { user } from "./auth";
import { createdAt, id, snapshot } from "./columns";
import { studies } from "./studies";

export const experiments = pgTable(
  "experiments",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    name: text("name").notNull(),
    description: text("description").notNull().default(""),
    // The robot plugin the experiment targets, by the plugin's robotId.
    robotId: text("robot_id").notNull(),
    // Whose document of that robot it runs when several sources offer it:
    // "first-party" or a repository's id; null: the default (first-party
    // first, then the repository that installed the robot first).
    pluginSource: text("plugin_source"),
    // Bumped by every saved design, so a save based on an older draft is refused.
    draftRevision: integer("draft_revision").notNull().default(0),
    createdAt: createdAt(),
    updatedAt: timestamp("updated_at", { withTimezone: true }).notNull().defaultNow(),
    updatedBy: text("updated_by").references(() => user.id, { onDelete: "set null" }),
  },
  (t) => [index("experiments_study_idx").on(t.studyId)],
);

export const steps = pgTable(
  "steps",
  {
    id: id(),
    experimentId: text("experiment_id")
      .notNull()
      .references(() => experiments.id, { onDelete: "cascade" }),
    position: integer("position").notNull(),
    name: text("name").notNull(),
    description: text("description").notNull().default(""),
    // Where the step leads once its actions are done (see core/protocol/document.ts).
    after: jsonb("after").$type<After>().notNull().default({ to: "next" }),
    // How long the step may last, and where it leads then; null: no limit.
    timeLimit: jsonb("time_limit").$type<TimeLimit>(),
    // The step's actions per condition, by the condition's name; null: the same in every condition.
    variants: jsonb("variants").$type<Record<string, StepVariant>>(),
  },
  (t) => [index("steps_experiment_idx").on(t.experimentId, t.position)],
);

export const actions = pgTable(
  "actions",
  {
    id: id(),
    stepId: text("step_id")
      .notNull()
      .references(() => steps.id, { onDelete: "cascade" }),
    position: integer("position").notNull(),
    type: text("type").notNull(),
    name: text("name").notNull().default(""),
    parameters: jsonb("parameters").notNull().default(sql`'{}'::jsonb`),
    // Actions sharing a group id start together.
    parallelGroup: text("parallel_group"),
    // Guidance shown to the wizard beside the action during a trial.
    note: text("note").notNull().default(""),
    // A record_answer's "no answer in N s" and where it leads then; null: no limit.
    timeLimit: jsonb("time_limit").$type<TimeLimit>(),
    // The action per condition (its parameters, maybe its type), by the condition's name; null: the same in every condition.
    variants: jsonb("variants").$type<Record<string, ActionVariant>>(),
  },
  (t) => [index("actions_step_idx").on(t.stepId, t.position)],
);

// An immutable, published snapshot of an experiment's design.
export const experimentVersions = pgTable(
  "experiment_versions",
  {
    id: id(),
    experimentId: text("experiment_id")
      .notNull()
      .references(() => experiments.id, { onDelete: "cascade" }),
    version: integer("version").notNull(),
    snapshot: snapshot("snapshot").notNull(),
    // SHA-256 over the canonical JSON of the snapshot.
    hash: text("hash").notNull(),
    // The robot it was published for (its plugin's robotId).
    robotId: text("robot_id").notNull(),
    pluginVersion: text("plugin_version"),
    // The exact plugin document (plugin_documents.hash) this version was published against.
    pluginHash: text("plugin_hash"),
    // Where that document came from ("first-party" or a repository's id): with robotId, pluginVersion and pluginHash, its identity.
    pluginSource: text("plugin_source"),
    publishedBy: text("published_by").references(() => user.id, { onDelete: "set null" }),
    publishedAt: timestamp("published_at", { withTimezone: true }).notNull().defaultNow(),
  },
  (t) => [uniqueIndex("experiment_versions_number_idx").on(t.experimentId, t.version)],
);
