// Code events in the database: what the runtime writes for an observer's key
// press during a trial, and what the analysis page's corrections go through.
// A code is always checked against a published scheme version of the trial's
// own study, and against that version's sets and codes.
import { and, asc, eq, inArray, isNull } from "drizzle-orm";
import { keyPress } from "@/core/coding/live";
import { findCode, type Scheme } from "@/core/coding/scheme";
import type { Database } from "./client";
import { codeEvents, codingSchemeVersions, codingSchemes, trials } from "./schema";

export type CodeEventRow = typeof codeEvents.$inferSelect;

/** A code event as the socket and the pages carry it. */
export type CodeEventView = Pick<
  CodeEventRow,
  "id" | "versionId" | "setId" | "codeId" | "kind" | "startMs" | "endMs" | "modifiers" | "observerId"
>;

export const codeView = (r: CodeEventRow): CodeEventView => ({
  id: r.id,
  versionId: r.versionId,
  setId: r.setId,
  codeId: r.codeId,
  kind: r.kind,
  startMs: r.startMs,
  endMs: r.endMs,
  modifiers: r.modifiers,
  observerId: r.observerId,
});

type Refusal = { ok: false; reason: string };

/** The scheme of a published version, if that version belongs to the trial's study. */
export async function schemeOfTrial(
  db: Pick<Database, "select">,
  versionId: string,
  trialId: string,
): Promise<Scheme | undefined> {
  const [row] = await db
    .select({ definition: codingSchemeVersions.definition })
    .from(codingSchemeVersions)
    .innerJoin(codingSchemes, eq(codingSchemes.id, codingSchemeVersions.schemeId))
    .innerJoin(trials, eq(trials.studyId, codingSchemes.studyId))
    .where(and(eq(codingSchemeVersions.id, versionId), eq(trials.id, trialId)));
  return row?.definition as Scheme | undefined;
}

/** The code a version's set and code id name, or why it cannot be used in this trial. */
export async function codeOfTrial(
  db: Pick<Database, "select">,
  trialId: string,
  mark: { versionId: string; setId: string; codeId: string; modifiers: string[] },
) {
  const scheme = await schemeOfTrial(db, mark.versionId, trialId);
  if (!scheme) return { ok: false, reason: "That coding scheme is not one of this study's." } as Refusal;
  const found = findCode(scheme, mark.setId, mark.codeId);
  if (!found) return { ok: false, reason: `“${scheme.name}” has no code ${mark.setId}/${mark.codeId}.` } as Refusal;
  const unknown = mark.modifiers.find((m) => !found.code.modifiers.includes(m));
  if (unknown !== undefined)
    return { ok: false, reason: `“${found.code.name}” has no modifier “${unknown}”.` } as Refusal;
  return { ok: true as const, ...found };
}

/**
 * An observer's key press in a running trial, at `atMs` on its clock: ends the
 * states it ends and begins what it begins, in one transaction. Returns every
 * code event it changed, for the observer's own tier.
 */
export async function pressCode(
  db: Database,
  by: { trialId: string; observerId: string },
  mark: { versionId: string; setId: string; codeId: string; modifiers: string[] },
  atMs: number,
): Promise<{ ok: true; changed: CodeEventView[] } | Refusal> {
  const found = await codeOfTrial(db, by.trialId, mark);
  if (!found.ok) return found;
  return db.transaction(async (tx) => {
    const mine = and(eq(codeEvents.trialId, by.trialId), eq(codeEvents.observerId, by.observerId));
    const open = await tx
      .select()
      .from(codeEvents)
      .where(
        and(mine, eq(codeEvents.kind, "state"), isNull(codeEvents.endMs), eq(codeEvents.versionId, mark.versionId)),
      )
      .for("update");
    const press = keyPress(open, found.set, found.code);
    const changed: CodeEventRow[] = [];
    if (press.end.length)
      changed.push(
        ...(await tx
          .update(codeEvents)
          .set({ endMs: atMs, updatedAt: new Date() })
          .where(inArray(codeEvents.id, press.end))
          .returning()),
      );
    if (press.start)
      changed.push(
        ...(await tx
          .insert(codeEvents)
          .values({
            trialId: by.trialId,
            observerId: by.observerId,
            versionId: mark.versionId,
            ...press.start,
            startMs: atMs,
            endMs: null,
            modifiers: mark.modifiers,
          })
          .returning()),
      );
    return { ok: true as const, changed: changed.map(codeView) };
  });
}

/** Every code event of a trial, in time order: each observer's tier. */
export const trialCodes = (db: Pick<Database, "select">, trialId: string) =>
  db
    .select()
    .from(codeEvents)
    .where(eq(codeEvents.trialId, trialId))
    .orderBy(asc(codeEvents.startMs), asc(codeEvents.id));
