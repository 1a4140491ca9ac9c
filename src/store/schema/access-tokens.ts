// Personal access tokens for the analysis API (R, Python): read-only, scoped
// to chosen studies, with an expiry. Only the SHA-256 of the secret is kept;
// the secret itself is shown once, when the token is made.
import { date, index, pgTable, primaryKey, text, timestamp } from "drizzle-orm/pg-core";
import { user } from "./auth";
import { createdAt, id } from "./columns";
import { studies } from "./studies";

export const accessTokens = pgTable(
  "access_tokens",
  {
    id: id(),
    userId: text("user_id")
      .notNull()
      .references(() => user.id, { onDelete: "cascade" }),
    name: text("name").notNull(),
    /** Hex SHA-256 of the secret: a stolen database holds no usable token. */
    secretHash: text("secret_hash").notNull().unique(),
    createdAt: createdAt(),
    expiresAt: timestamp("expires_at", { withTimezone: true }).notNull(),
    lastUsedAt: timestamp("last_used_at", { withTimezone: true }),
    revokedAt: timestamp("revoked_at", { withTimezone: true }),
    /** The day (UTC) the token's use was last written to the audit log: one entry per token per day. */
    auditedOn: date("audited_on", { mode: "string" }),
  },
  (t) => [index("access_tokens_user_idx").on(t.userId)],
);

/** The studies a token may read; a study's deletion takes it out of every token. */
export const accessTokenStudies = pgTable(
  "access_token_studies",
  {
    tokenId: text("token_id")
      .notNull()
      .references(() => accessTokens.id, { onDelete: "cascade" }),
    studyId: text("study_id")
      .notNull()
      .references(() => studies.id, { onDelete: "cascade" }),
  },
  (t) => [primaryKey({ columns: [t.tokenId, t.studyId] }), index("access_token_studies_study_idx").on(t.studyId)],
);
