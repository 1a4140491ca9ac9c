// The code events of some trials, each with its observer's name and the
// scheme version it was coded with: what every export of codes is made from.
import { asc, eq, inArray } from "drizzle-orm";
import type { CodeRowInput } from "@/core/coding/export";
import type { Scheme } from "@/core/coding/scheme";
import type { Database } from "@/store/client";
import { codeEvents, codingSchemeVersions, user } from "@/store/schema";

export async function codeRowsOf(db: Pick<Database, "select">, trialIds: string[]): Promise<CodeRowInput[]> {
  if (!trialIds.length) return [];
  const rows = await db
    .select({
      code: codeEvents,
      observer: user.name,
      definition: codingSchemeVersions.definition,
      version: codingSchemeVersions.version,
    })
    .from(codeEvents)
    .innerJoin(codingSchemeVersions, eq(codingSchemeVersions.id, codeEvents.versionId))
    .leftJoin(user, eq(user.id, codeEvents.observerId))
    .where(inArray(codeEvents.trialId, trialIds))
    .orderBy(asc(codeEvents.trialId), asc(codeEvents.startMs), asc(codeEvents.id));
  return rows.map((r) => ({
    trialId: r.code.trialId,
    observer: r.observer ?? "(former member)",
    scheme: r.definition as Scheme,
    schemeVersion: r.version,
    setId: r.code.setId,
    codeId: r.code.codeId,
    kind: r.code.kind,
    startMs: r.code.startMs,
    endMs: r.code.endMs,
    modifiers: r.code.modifiers,
  }));
}
