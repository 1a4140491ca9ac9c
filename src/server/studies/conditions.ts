// A study's condition, stored one way for the conditions tab and for a study
// made from a template.
import { TRPCError } from "@trpc/server";
import type { Database } from "@/store/client";
import { conditions } from "@/store/schema";
import type { Tx } from "../experiments/design";

/** The experiment must be the study's own: the caller has checked it. */
export async function insertCondition(
  db: Database | Tx,
  studyId: string,
  condition: { name: string; description: string; experimentId: string },
) {
  const [row] = await db
    .insert(conditions)
    .values({ ...condition, studyId })
    .returning()
    .catch((e: { cause?: { code?: string } }) => {
      if (e.cause?.code === "23505")
        throw new TRPCError({
          code: "CONFLICT",
          message: `This study already has a condition called ${condition.name}.`,
        });
      throw e;
    });
  return row!;
}
