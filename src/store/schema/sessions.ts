// A study's planned sessions: who comes, in which condition, when, and which
// wizard runs it. Starting a session makes its trial.
import { index, pgTable, text, timestamp } from "drizzle-orm/pg-core";
import { user } from "./auth";
import { createdAt, id } from "./columns";
import { conditions, participants, studies } from "./studies";
import { trials } from "./trials";

export const sessions = pgTable(
  "sessions",
  {
    id: id(),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
    participantId: text("participant_id")
      .notNull()
      .references(() => participants.id, { onDelete: "restrict" }),
    conditionId: text("condition_id")
      .notNull()
      .references(() => conditions.id, { onDelete: "restrict" }),
    wizardId: text("wizard_id").references(() => user.id, { onDelete: "set null" }),
    plannedAt: timestamp("planned_at", { withTimezone: true }).notNull(),
    trialId: text("trial_id").references(() => trials.id, { onDelete: "set null" }),
    createdBy: text("created_by").references(() => user.id, { onDelete: "set null" }),
    createdAt: createdAt(),
  },
  (t) => [
    index("sessions_study_idx").on(t.studyId, t.plannedAt),
    index("sessions_wizard_idx").on(t.wizardId, t.plannedAt),
    index("sessions_participant_idx").on(t.participantId),
    index("sessions_condition_idx").on(t.conditionId),
    index("sessions_trial_idx").on(t.trialId),
  ],
);
