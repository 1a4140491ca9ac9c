// Trials with participants run only in an active study (rehearsals run anywhere).
import { TRPCError } from "@trpc/server";
import { eq } from "drizzle-orm";
import { trialRefusal } from "@/core/studies/status";
import type { Database } from "@/store/client";
import { studies } from "@/store/schema";

export async function assertRunsTrials(db: Database, studyId: string) {
  const [study] = await db.select({ status: studies.status }).from(studies).where(eq(studies.id, studyId));
  const refusal = trialRefusal(study!.status);
  if (refusal) throw new TRPCError({ code: "PRECONDITION_FAILED", message: refusal });
}
