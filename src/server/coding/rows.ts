// The code events of some trials, each with its observer's name and the
// scheme version it was coded with: what every export of codes is made from.
// The scheme is named as it is called now, so a team that renames "New coding
// scheme" after coding sees the new name in every export.
// By trial, then by start (ties in id order).
import { and, asc, eq, inArray, type SQL } from "drizzle-orm";
import type { CodeRowInput } from "@/core/coding/export";
import type { Scheme } from "@/core/coding/scheme";
import type { Database } from "@/store/client";
import { after, keyedPages } from "@/store/pages";
import { codeEvents, codingSchemes, codingSchemeVersions, user } from "@/store/schema";

/** The code events `where` picks, at most `limit` of them if given; each with its id, the key a page ends at. */
async function codeRows(db: Pick<Database, "select">, where: SQL | undefined, limit?: number) {
  const query = db
    .select({
      code: codeEvents,
      observer: user.name,
      definition: codingSchemeVersions.definition,
      schemeName: codingSchemes.name,
      version: codingSchemeVersions.version,
    })
    .from(codeEvents)
    .innerJoin(codingSchemeVersions, eq(codingSchemeVersions.id, codeEvents.versionId))
    .innerJoin(codingSchemes, eq(codingSchemes.id, codingSchemeVersions.schemeId))
    .leftJoin(user, eq(user.id, codeEvents.observerId))
    .where(where)
    .orderBy(asc(codeEvents.trialId), asc(codeEvents.startMs), asc(codeEvents.id))
    .$dynamic();
  return (await (limit ? query.limit(limit) : query)).map((r): CodeRowInput & { id: string } => ({
    trialId: r.code.trialId,
    observer: r.observer ?? "(former member)",
    scheme: { ...(r.definition as Scheme), name: r.schemeName },
    schemeVersion: r.version,
    setId: r.code.setId,
    codeId: r.code.codeId,
    kind: r.code.kind,
    startMs: r.code.startMs,
    endMs: r.code.endMs,
    modifiers: r.code.modifiers,
    id: r.code.id,
  }));
}

export async function codeRowsOf(db: Pick<Database, "select">, trialIds: string[]): Promise<CodeRowInput[]> {
  return trialIds.length ? codeRows(db, inArray(codeEvents.trialId, trialIds)) : [];
}

/** One trial's code events a page at a time (see keyedPages), in codeRowsOf's order. */
export function codePages(db: Pick<Database, "select">, trialId: string, limit: number) {
  const key = [codeEvents.startMs, codeEvents.id];
  return keyedPages(
    (from) => codeRows(db, and(eq(codeEvents.trialId, trialId), after(key, from)), limit),
    (c) => [c.startMs, c.id],
    limit,
  );
}
