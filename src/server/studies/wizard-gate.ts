// Who may be named a trial's or a session's wizard: a member of the study who
// may run its trials (the policy's "trial.run"), never an observer or a stranger.
import { TRPCError } from "@trpc/server";
import { and, eq } from "drizzle-orm";
import { studyRoleMay } from "@/core/access/policy";
import type { Database } from "@/store/client";
import { studyMembers } from "@/store/schema";

export async function assertWizardOf(db: Database, studyId: string, wizardId: string) {
  const [member] = await db
    .select({ role: studyMembers.role })
    .from(studyMembers)
    .where(and(eq(studyMembers.studyId, studyId), eq(studyMembers.userId, wizardId)));
  if (!member || !studyRoleMay(member.role, "trial.run"))
    throw new TRPCError({
      code: "BAD_REQUEST",
      message: "Please correct: wizardId: the wizard must be an owner, researcher or wizard of this study",
    });
}
