// The check that an input names rows of one study only.
import { TRPCError } from "@trpc/server";
import { namedIn } from "@/core/access/input";
import type { Database } from "@/store/client";
import { studyAccessOf } from "@/store/study-access";
import { loadResource, nameOf, REFERENCES, type ReferenceKey } from "./resources";

type Db = Pick<Database, "select">;

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
export async function assertOneStudy(
  db: Db,
  studyId: string,
  input: unknown,
  known: { kind: string; id: string },
): Promise<void> {
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
