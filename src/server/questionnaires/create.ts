// A study's questionnaire, stored one way for the questionnaires tab and for
// a study made from a template: a draft, unpublished until someone publishes it.
import type { Definition } from "@/core/questionnaires/definition";
import type { Database } from "@/store/client";
import { questionnaires } from "@/store/schema";
import type { Tx } from "../experiments/design";

export async function insertQuestionnaire(
  db: Database | Tx,
  studyId: string,
  questionnaire: { name: string; draft: Definition; timing?: "before" | "after" | "none" },
) {
  const [row] = await db
    .insert(questionnaires)
    .values({ ...questionnaire, studyId })
    .returning({ id: questionnaires.id });
  return row!;
}
