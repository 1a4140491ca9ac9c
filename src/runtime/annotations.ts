import { eq } from "drizzle-orm";
import type { Database } from "@/store/client";
import { annotations, trials } from "@/store/schema";

/** A annotation, timed on the trial's clock (0 before the trial starts). */
export async function annotate(
  db: Database,
  by: { trialId: string; userId: string; name: string },
  label: string,
  note: string,
) {
  const [trial] = await db.select({ t0: trials.t0 }).from(trials).where(eq(trials.id, by.trialId));
  const relMs = trial?.t0 ? Date.now() - trial.t0.getTime() : 0;
  const [row] = await db
    .insert(annotations)
    .values({ trialId: by.trialId, authorId: by.userId, relMs, label, note })
    .returning();
  return { id: row!.id, relMs, label, note, authorName: by.name };
}
