// A new study from another one as a template: its design, never its data.
// Copied: the settings that are design (decided one by one in
// core/studies/template.ts), every experiment's draft, the conditions (each
// bound to the copy of its experiment), the questionnaires' and coding schemes' drafts. Never
// copied: participants, sessions, trials and their events, recordings,
// annotations, questionnaire links and answers, published versions, the audit
// log, and members: the creator is the new study's only member, its owner.
import { randomBytes } from "node:crypto";
import { asc, eq } from "drizzle-orm";
import { readSettings } from "@/core/studies/settings";
import { templateSettings } from "@/core/studies/template";
import type { Definition } from "@/core/questionnaires/definition";
import type { Database } from "@/store/client";
import type { Scheme } from "@/core/coding/scheme";
import { codingSchemes, conditions, experiments, questionnaires, studies } from "@/store/schema";
import { insertScheme } from "../coding/schemes";
import { duplicate } from "../experiments/exchange";
import { insertQuestionnaire } from "../questionnaires/create";
import { createStudy } from "./create";
import { insertCondition } from "./conditions";

export async function studyFromTemplate(
  db: Database,
  sourceId: string,
  userId: string,
  study: { title: string; description?: string },
) {
  // One transaction: a copy that fails half-way (a robot whose plugin is gone) leaves no half study behind.
  return db.transaction(async (tx) => {
    const [source] = await tx.select().from(studies).where(eq(studies.id, sourceId));
    const created = await createStudy(
      tx,
      userId,
      {
        title: study.title,
        description: study.description ?? source!.description,
        // The new study starts as a draft (the column's default): it has run nothing yet.
        settings: templateSettings(readSettings(source!.settings), () => randomBytes(12).toString("hex")),
      },
      { template: { studyId: source!.id, title: source!.title } },
    );
    // Each experiment's draft, not its published versions: the draft is the
    // design as its researchers keep it now (a published version is its past),
    // and the new study publishes its own versions before running trials. The
    // copies keep their names: in a new study there is no original to tell apart.
    const copyOf = new Map<string, string>();
    const sourceExperiments = await tx
      .select({ id: experiments.id })
      .from(experiments)
      .where(eq(experiments.studyId, source!.id))
      .orderBy(asc(experiments.createdAt), asc(experiments.id));
    for (const e of sourceExperiments) copyOf.set(e.id, (await duplicate(tx, e.id, userId, created.id)).id);
    const sourceConditions = await tx
      .select()
      .from(conditions)
      .where(eq(conditions.studyId, source!.id))
      .orderBy(asc(conditions.createdAt), asc(conditions.id));
    for (const c of sourceConditions)
      await insertCondition(tx, created.id, {
        name: c.name,
        description: c.description,
        experimentId: copyOf.get(c.experimentId)!,
      });
    // Questionnaires as unpublished drafts: a published version is what the
    // source's participants answered; the new study publishes its own, and an
    // unchanged definition publishes with the same hash, so the two can be
    // shown to be the same instrument.
    const sourceQuestionnaires = await tx
      .select()
      .from(questionnaires)
      .where(eq(questionnaires.studyId, source!.id))
      .orderBy(asc(questionnaires.createdAt), asc(questionnaires.id));
    for (const q of sourceQuestionnaires)
      await insertQuestionnaire(tx, created.id, { name: q.name, draft: q.draft as Definition, timing: q.timing });
    // Coding schemes the same way: drafts, published afresh (same scheme, same hash), never the source's codes.
    const sourceSchemes = await tx
      .select()
      .from(codingSchemes)
      .where(eq(codingSchemes.studyId, source!.id))
      .orderBy(asc(codingSchemes.createdAt), asc(codingSchemes.id));
    for (const s of sourceSchemes) await insertScheme(tx, created.id, s.draft as Scheme);
    return created;
  });
}
