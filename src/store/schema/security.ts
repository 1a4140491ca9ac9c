// What the server remembers to keep its doors shut: socket tokens already
// used (each works once), and failed sign-ins per address and per account.
import { integer, pgTable, text, timestamp } from "drizzle-orm/pg-core";

export const socketTokenUses = pgTable("socket_token_uses", {
  tokenId: text("token_id").primaryKey(),
  userId: text("user_id").notNull(),
  trialId: text("trial_id").notNull(),
  usedAt: timestamp("used_at", { withTimezone: true }).notNull().defaultNow(),
  // Kept until the token would have expired anyway; later rows can be purged.
  expiresAt: timestamp("expires_at", { withTimezone: true }).notNull(),
});

/** `key` is "address:<ip>" or "account:<email>"; counts failures inside a window. */
export const signInThrottle = pgTable("sign_in_throttle", {
  key: text("key").primaryKey(),
  failures: integer("failures").notNull().default(0),
  windowStartedAt: timestamp("window_started_at", { withTimezone: true }).notNull().defaultNow(),
});
