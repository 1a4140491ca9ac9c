// A new study, its creator its owner, on the record: the one way a study is
// made, whether blank or from another study as a template.
import type { StudySettings } from "@/core/studies/settings";
import { studies, studyMembers } from "@/store/schema";
import { audit } from "../audit";
import type { Tx } from "../experiments/design";

export async function createStudy(
  tx: Tx,
  userId: string,
  study: { title: string; description: string; settings?: StudySettings },
  /** What the audit log says of where it came from (a template). */
  details?: Record<string, unknown>,
) {
  const [row] = await tx
    .insert(studies)
    .values({ title: study.title, description: study.description, settings: study.settings, createdBy: userId })
    .returning();
  await tx.insert(studyMembers).values({ studyId: row!.id, userId, role: "owner" });
  await audit(tx, { actorId: userId, studyId: row!.id, action: "study.create", target: row!.id, details });
  return row!;
}
