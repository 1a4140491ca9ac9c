// The lab's physical robots, as records an administrator keeps: which plugin
// drives each, how to reach it, and which studies may use it. Secrets are
// never stored: a record names where to read one (an environment variable or
// a file) and the runtime reads it when it connects. The live health columns
// are written by the runtime that drives (or last drove) the robot.
import { boolean, doublePrecision, index, integer, pgTable, primaryKey, text, timestamp } from "drizzle-orm/pg-core";
import { createdAt, id } from "./columns";
import { studies } from "./studies";

export const robots = pgTable("robots", {
  id: id(),
  name: text("name").notNull().unique(),
  // The plugin's robotId; null: runs any plugin (a simulated robot; the environment's robot, as before records).
  pluginRobotId: text("plugin_robot_id"),
  simulated: boolean("simulated").notNull().default(false),
  rosbridgeUrl: text("rosbridge_url"),
  sshHost: text("ssh_host"),
  sshPort: integer("ssh_port").notNull().default(22),
  sshUser: text("ssh_user"),
  // "env:NAME" or "file:/path": where the SSH password or private key is read (src/core/robots/secrets.ts).
  sshSecret: text("ssh_secret"),
  httpUrl: text("http_url"),
  // Available to every study (the simulated robots by default); otherwise only to those in robot_studies.
  allStudies: boolean("all_studies").notNull().default(false),
  // Seeded from the environment or the launcher: seeding again updates it rather than adding another.
  seededFrom: text("seeded_from").unique(),
  connected: boolean("connected").notNull().default(false),
  battery: doublePrecision("battery"),
  lastSeenAt: timestamp("last_seen_at", { withTimezone: true }),
  createdAt: createdAt(),
});

export const robotStudies = pgTable(
  "robot_studies",
  {
    robotId: text("robot_id")
      .notNull()
      .references(() => robots.id, { onDelete: "cascade" }),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
  },
  (t) => [primaryKey({ columns: [t.robotId, t.studyId] }), index("robot_studies_study_idx").on(t.studyId)],
);
