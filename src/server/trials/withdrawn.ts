import { TRPCError } from "@trpc/server";
import { eq } from "drizzle-orm";
import type { Database } from "@/store/client";
import { participants, trials } from "@/store/schema";

/** A withdrawn participant's data leaves analysis and exports; the withdrawal itself stays in the audit log. */
export async function assertNotWithdrawn(db: Database, trialId: string) {
  const [row] = await db
    .select({ code: participants.code, status: participants.consentStatus })
    .from(trials)
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .where(eq(trials.id, trialId));
  if (row?.status === "withdrawn") {
    throw new TRPCError({
      code: "PRECONDITION_FAILED",
      message: `${row.code} withdrew from the study: their data is excluded from analysis and exports.`,
    });
  }
}
