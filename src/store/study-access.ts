// The caller's place in a study: read by every tRPC procedure and every
// trial socket command, so it sits below both servers.
import { and, eq } from "drizzle-orm";
import type { StudyRole } from "@/core/access/policy";
import { blindingFor, NOT_BLINDED, type Blinding } from "@/core/studies/blinding";
import { readSettings } from "@/core/studies/settings";
import type { StudyStatus } from "@/core/studies/status";
import type { Database } from "./client";
import { studies, studyMembers } from "./schema";

type Db = Pick<Database, "select">;

/** The caller's role in a study, what that study's blinds hide from them, and the study's status. */
export async function studyAccessOf(
  db: Db,
  studyId: string,
  userId: string,
): Promise<{ role: StudyRole | null; blinding: Blinding; status: StudyStatus }> {
  const [row] = await db
    .select({ role: studyMembers.role, settings: studies.settings, status: studies.status })
    .from(studies)
    .leftJoin(studyMembers, and(eq(studyMembers.studyId, studies.id), eq(studyMembers.userId, userId)))
    .where(eq(studies.id, studyId));
  const role = row?.role ?? null;
  return {
    role,
    blinding: row ? blindingFor(role, readSettings(row.settings), row.status) : NOT_BLINDED,
    status: row?.status ?? "draft",
  };
}
