// A study's coding schemes, stored one way for the Coding tab and for a study
// made from a template: a draft, unpublished until someone publishes it, and
// the latest published version of each, which observers code with.
import { TRPCError } from "@trpc/server";
import { desc, eq, sql } from "drizzle-orm";
import { COUNTED_BY_DEFAULT, type Counted } from "@/core/coding/counted";
import { checkScheme, type Scheme } from "@/core/coding/scheme";
import { hashCanonical } from "@/core/protocol/canonical";
import type { Database } from "@/store/client";
import { codingSchemeVersions, codingSchemes } from "@/store/schema";
import type { Tx } from "../experiments/design";

export async function insertScheme(db: Database | Tx, studyId: string, draft: Scheme) {
  const [row] = await db
    .insert(codingSchemes)
    .values({ studyId, name: draft.name, draft })
    .returning({ id: codingSchemes.id });
  return row!;
}

/** The scheme as given, or every problem with it in one plain message. */
export function checkedScheme(definition: unknown): Scheme {
  const checked = checkScheme(definition);
  if (checked.ok) return checked.scheme;
  throw new TRPCError({
    code: "BAD_REQUEST",
    message: `Please correct: ${checked.problems.map((p) => `definition.${p}`).join("; ")}`,
  });
}

/** Each scheme of the study at its latest published version: what observers code with. */
export async function publishedSchemes(db: Database, studyId: string) {
  const rows = await db
    .selectDistinctOn([codingSchemeVersions.schemeId], {
      versionId: codingSchemeVersions.id,
      schemeId: codingSchemeVersions.schemeId,
      version: codingSchemeVersions.version,
      definition: codingSchemeVersions.definition,
    })
    .from(codingSchemeVersions)
    .innerJoin(codingSchemes, eq(codingSchemes.id, codingSchemeVersions.schemeId))
    .where(eq(codingSchemes.studyId, studyId))
    .orderBy(codingSchemeVersions.schemeId, desc(codingSchemeVersions.version));
  return rows.map((r) => ({ ...r, definition: r.definition as Scheme }));
}

/** Freezes a scheme's draft as its next numbered version. */
export function publishScheme(db: Database, schemeId: string, userId: string) {
  return db.transaction(async (tx) => {
    const [s] = await tx.select().from(codingSchemes).where(eq(codingSchemes.id, schemeId)).for("update");
    // What coders code with; how agreement is counted stays the scheme's, changed without a new version.
    const { counted: _, ...definition } = checkedScheme(s!.draft);
    const [{ next }] = (await tx
      .select({ next: sql<number>`coalesce(max(${codingSchemeVersions.version}), 0)::int + 1` })
      .from(codingSchemeVersions)
      .where(eq(codingSchemeVersions.schemeId, schemeId))) as [{ next: number }];
    const [version] = await tx
      .insert(codingSchemeVersions)
      .values({ schemeId, version: next, definition, hash: hashCanonical(definition), publishedBy: userId })
      .returning({
        id: codingSchemeVersions.id,
        version: codingSchemeVersions.version,
        hash: codingSchemeVersions.hash,
      });
    return version!;
  });
}

/** How a scheme's agreement is counted: as kept on its draft, or by default. */
export async function keptCounted(db: Pick<Database, "select">, schemeId: string): Promise<Counted> {
  const [row] = await db
    .select({ draft: codingSchemes.draft })
    .from(codingSchemes)
    .where(eq(codingSchemes.id, schemeId));
  return (row?.draft as Scheme | undefined)?.counted ?? COUNTED_BY_DEFAULT;
}
