// The per-account sign-in counter in `sign_in_throttle`, shared by every copy
// of the app. Each statement is one atomic upsert, so parallel attempts on one
// account each see their own count.
import { and, eq, gt, lt, sql } from "drizzle-orm";
import { accountKey, windowCutoff, type AccountCount, type AccountLimit } from "@/core/access/sign-in-throttle";
import type { Database } from "@/store/client";
import { signInThrottle } from "@/store/schema";

/** Counts one attempt on the account (a new window if the last one is over) and returns the counter. */
export async function countAttempt(db: Database, email: string, limit: AccountLimit, now: Date): Promise<AccountCount> {
  const cutoff = windowCutoff(now, limit);
  const over = sql`${signInThrottle.windowStartedAt} <= ${cutoff.toISOString()}::timestamptz`;
  const [row] = await db
    .insert(signInThrottle)
    .values({ key: accountKey(email), failures: 1, windowStartedAt: now })
    .onConflictDoUpdate({
      target: signInThrottle.key,
      set: {
        failures: sql`CASE WHEN ${over} THEN 1 ELSE ${signInThrottle.failures} + 1 END`,
        windowStartedAt: sql`CASE WHEN ${over} THEN ${now.toISOString()}::timestamptz ELSE ${signInThrottle.windowStartedAt} END`,
      },
    })
    .returning({ failures: signInThrottle.failures, windowStartedAt: signInThrottle.windowStartedAt });
  if (row!.failures === 1) {
    // A new window began: forget the counters whose windows are over.
    await db.delete(signInThrottle).where(lt(signInThrottle.windowStartedAt, cutoff));
  }
  return row!;
}

/** Takes back the attempt that just succeeded; the failures other attempts left on the account stay counted. */
export async function forgiveAttempt(db: Database, email: string, limit: AccountLimit, now: Date): Promise<void> {
  const current = gt(signInThrottle.windowStartedAt, windowCutoff(now, limit));
  await db
    .update(signInThrottle)
    .set({ failures: sql`GREATEST(${signInThrottle.failures} - 1, 0)` })
    .where(and(eq(signInThrottle.key, accountKey(email)), current));
}
