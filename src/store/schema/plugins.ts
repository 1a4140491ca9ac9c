import { boolean, jsonb, pgTable, text, timestamp, uniqueIndex } from "drizzle-orm/pg-core";
import { user } from "./auth";
import { createdAt, id } from "./columns";

export const pluginRepositories = pgTable("plugin_repositories", {
  id: id(),
  url: text("url").notNull().unique(),
  name: text("name").notNull(),
  // Chosen by the administrator who added the repository: the most its plugins are trusted.
  trust: text("trust", { enum: ["official", "verified", "community"] })
    .notNull()
    .default("community"),
  enabled: boolean("enabled").notNull().default(true),
  lastSyncedAt: timestamp("last_synced_at", { withTimezone: true }),
  lastSyncError: text("last_sync_error"),
  createdBy: text("created_by").references(() => user.id, { onDelete: "set null" }),
  createdAt: createdAt(),
});

// One row per plugin version of a repository: its identity is repository, robotId, version and hash.
export const installedPlugins = pgTable(
  "installed_plugins",
  {
    id: id(),
    // Null for the first-party plugins shipped in plugins/.
    repositoryId: text("repository_id").references(() => pluginRepositories.id, { onDelete: "cascade" }),
    robotId: text("robot_id").notNull(),
    version: text("version").notNull(),
    name: text("name").notNull(),
    trustLevel: text("trust_level").notNull(),
    definition: jsonb("definition").notNull(),
    hash: text("hash").notNull(),
    installedAt: createdAt(),
  },
  (t) => [uniqueIndex("installed_plugins_repository_robot_version_idx").on(t.repositoryId, t.robotId, t.version)],
);

// Every plugin document a published version ran against, by its content hash:
// the runtime loads exactly this document for the version's trials.
export const pluginDocuments = pgTable("plugin_documents", {
  hash: text("hash").primaryKey(),
  robotId: text("robot_id").notNull(),
  version: text("version").notNull(),
  // "first-party", or the repository's id.
  source: text("source").notNull(),
  definition: jsonb("definition").notNull(),
  createdAt: createdAt(),
});
