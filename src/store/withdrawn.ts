// A withdrawn participant's data leaves analysis, exports and replays; the
// withdrawal itself stays in the audit log. Asked by the web server and the runtime alike.
import { eq } from "drizzle-orm";
import type { Database } from "./client";
import { participants, trials } from "./schema";

/** Why the trial's data may not be read (its participant withdrew), or null when it may. */
export async function withdrawnFrom(db: Pick<Database, "select">, trialId: string): Promise<string | null> {
  const [row] = await db
    .select({ code: participants.code, status: participants.consentStatus })
    .from(trials)
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .where(eq(trials.id, trialId));
  return row?.status === "withdrawn"
    ? `${row.code} withdrew from the study: their data is excluded from analysis and exports.`
    : null;
}
