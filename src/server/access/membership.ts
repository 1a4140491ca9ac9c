// The caller's place in a study, and the check that an input names rows of
// one study only.
import { TRPCError } from "@trpc/server";
import { and, eq } from "drizzle-orm";
import { namedIn } from "@/core/access/input";
import type { StudyRole } from "@/core/access/policy";
import { blindingFor, NOT_BLINDED, type Blinding } from "@/core/studies/blinding";
import { readSettings } from "@/core/studies/settings";
import type { Database } from "../db/client";
import { studies, studyMembers } from "../db/schema";
import { loadResource, nameOf, REFERENCES, type ReferenceKey } from "./resources";

type Db = Pick<Database, "select">;

/** The caller's role in a study, and what that study's blinds hide from them. */
export async function studyAccessOf(db: Db, studyId: string, userId: string): Promise<{ role: StudyRole | null; blinding: Blinding }> {
  const [row] = await db
    .select({ role: studyMembers.role, settings: studies.settings, status: studies.status })
    .from(studies)
    .leftJoin(studyMembers, and(eq(studyMembers.studyId, studies.id), eq(studyMembers.userId, userId)))
    .where(eq(studies.id, studyId));
  const role = row?.role ?? null;
  return { role, blinding: row ? blindingFor(role, readSettings(row.settings), row.status) : NOT_BLINDED };
}

const REFERENCE_KEYS = new Set(Object.keys(REFERENCES));
const MAX_REFERENCES = 1000;

const refuse = (path: string, what: string): never => {
  throw new TRPCError({ code: "BAD_REQUEST", message: `Please correct: ${path}: ${what}` });
};

/**
 * Refuses an input that names a row of any other study, wherever in the input
 * it sits, under any key the schema may or may not use: an unknown id and
 * another study's id read the same.
 */
export async function assertOneStudy(db: Db, studyId: string, input: unknown, known: { kind: string; id: string }): Promise<void> {
  const named = namedIn(input, REFERENCE_KEYS).filter((n) => n.value !== null && n.value !== undefined);
  const checked = new Set([`${known.kind}:${known.id}`]);
  for (const { path, key, value } of named) {
    const ids = Array.isArray(value) ? value : [value];
    if (ids.length > MAX_REFERENCES) refuse(path, `may list at most ${MAX_REFERENCES} ids`);
    for (const [i, id] of ids.entries()) {
      const where = Array.isArray(value) ? `${path}.${i}` : path;
      if (typeof id !== "string" || id.length === 0 || id.length > 100) refuse(where, "must be an id");
      const kind = REFERENCES[key as ReferenceKey];
      if (checked.has(`${kind}:${id}`)) continue;
      if (kind === "member") {
        if ((await studyAccessOf(db, studyId, id as string)).role === null) refuse(where, "not a member of this study");
      } else if ((await loadResource(db, kind, id as string))?.studyId !== studyId) {
        refuse(where, `not a ${nameOf(kind)} of this study`);
      }
      checked.add(`${kind}:${id}`);
    }
  }
}
