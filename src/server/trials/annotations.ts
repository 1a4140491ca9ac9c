// A trial's annotations as its files hold them: in time order (ties in id
// order), each with its author's name (null once the account is deleted).
import { and, asc, eq, inArray, type SQL } from "drizzle-orm";
import type { Database } from "@/store/client";
import { after, keyedPages } from "@/store/pages";
import { annotations, user } from "@/store/schema";

/** The annotations `where` picks, by trial, at most `limit` if given; each with its trial and id, the key a page ends at. */
function annotationRows(db: Database, where: SQL | undefined, limit?: number) {
  const query = db
    .select({
      trialId: annotations.trialId,
      relMs: annotations.relMs,
      label: annotations.label,
      note: annotations.note,
      authorName: user.name,
      id: annotations.id,
    })
    .from(annotations)
    .leftJoin(user, eq(user.id, annotations.authorId))
    .where(where)
    .orderBy(asc(annotations.trialId), asc(annotations.relMs), asc(annotations.id))
    .$dynamic();
  return limit ? query.limit(limit) : query;
}

/** Every annotation of these trials in one query. */
export async function annotationsOf(db: Database, trialIds: string[]) {
  return trialIds.length ? annotationRows(db, inArray(annotations.trialId, trialIds)) : [];
}

/** One trial's annotations a page at a time (see keyedPages), in annotationsOf's order. */
export function annotationPages(db: Database, trialId: string, limit: number) {
  const key = [annotations.relMs, annotations.id];
  return keyedPages(
    async (from) => annotationRows(db, and(eq(annotations.trialId, trialId), after(key, from)), limit),
    (a) => [a.relMs, a.id],
    limit,
  );
}
