import { TRPCError } from "@trpc/server";
import type { Database } from "@/store/client";
import { withdrawnFrom } from "@/store/withdrawn";

/** A withdrawn participant's data leaves analysis and exports; the withdrawal itself stays in the audit log. */
export async function assertNotWithdrawn(db: Database, trialId: string) {
  const withdrawn = await withdrawnFrom(db, trialId);
  if (withdrawn) throw new TRPCError({ code: "PRECONDITION_FAILED", message: withdrawn });
}
