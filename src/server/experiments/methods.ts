// The methods text of a published version, with what the pure description
// needs from the study: the robot as its pinned plugin names it, the
// conditions and how participants are assigned, the questionnaires given
// around the trial. Read by the designer's preview and the study zip.
import { asc, desc, eq } from "drizzle-orm";
import { actionNamesOf } from "@/core/designer/action-name";
import type { Plugin } from "@/core/plugins";
import { type MethodsInput, methodsMarkdown, methodsPlainText } from "@/core/protocol/methods";
import { readSnapshot } from "@/core/protocol/snapshot";
import type { Definition } from "@/core/questionnaires/definition";
import { readSettings, type StudySettings } from "@/core/studies/settings";
import type { Database } from "@/store/client";
import {
  conditions,
  type experimentVersions,
  experiments,
  pluginDocuments,
  questionnaireVersions,
  questionnaires,
  studies,
} from "@/store/schema";
import { findPlugin } from "@/robots/catalog";
import { fileSlug } from "../file-slug";

type Reader = Pick<Database, "select">;
type VersionRow = typeof experimentVersions.$inferSelect;

export interface MethodsText {
  markdown: string;
  text: string;
  /** e.g. "interactive-storyteller-v3-methods.md" */
  filename: string;
}

/** The methods text of one version, given its row and its study. */
export async function methodsText(db: Reader, version: VersionRow, studyId: string): Promise<MethodsText> {
  const snapshot = readSnapshot(version.snapshot);
  const plugin = await pinnedPlugin(db, version);
  const [study] = await db.select({ settings: studies.settings }).from(studies).where(eq(studies.id, studyId));
  const input: MethodsInput = {
    snapshot,
    version: version.version,
    hash: version.hash,
    robot: { name: plugin?.name ?? version.robotId, pluginVersion: version.pluginVersion },
    conditions: await db
      .select({ name: conditions.name, description: conditions.description, experiment: experiments.name })
      .from(conditions)
      .innerJoin(experiments, eq(experiments.id, conditions.experimentId))
      .where(eq(conditions.studyId, studyId))
      .orderBy(asc(conditions.name)),
    assignment: assignmentOf(readSettings(study?.settings)),
    questionnaires: await givenQuestionnaires(db, studyId),
    names: actionNamesOf(plugin),
    events: plugin?.events,
  };
  return {
    markdown: methodsMarkdown(input),
    text: methodsPlainText(input),
    filename: `${fileSlug(snapshot.experiment.name, "experiment")}-v${version.version}-methods.md`,
  };
}

/** The plugin document the version was published against; the installed one for a version from before pinning. */
export async function pinnedPlugin(db: Reader, version: VersionRow): Promise<Plugin | null> {
  if (version.pluginHash) {
    const [document] = await db
      .select({ definition: pluginDocuments.definition })
      .from(pluginDocuments)
      .where(eq(pluginDocuments.hash, version.pluginHash));
    if (document) return document.definition as Plugin;
  }
  return (await findPlugin(db, version.robotId, version.pluginSource)) ?? null;
}

/** Questionnaires attached before or after the trial, each as participants see it: its latest published version, else its draft. */
export async function givenQuestionnaires(db: Reader, studyId: string): Promise<MethodsInput["questionnaires"]> {
  const rows = await db
    .select({
      id: questionnaires.id,
      name: questionnaires.name,
      timing: questionnaires.timing,
      draft: questionnaires.draft,
    })
    .from(questionnaires)
    .where(eq(questionnaires.studyId, studyId))
    .orderBy(asc(questionnaires.name));
  const given = rows.filter((q) => q.timing !== "none");
  return Promise.all(
    given.map(async (q) => {
      const [latest] = await db
        .select({ definition: questionnaireVersions.definition })
        .from(questionnaireVersions)
        .where(eq(questionnaireVersions.questionnaireId, q.id))
        .orderBy(desc(questionnaireVersions.version))
        .limit(1);
      const definition = (latest?.definition ?? q.draft) as Partial<Definition>;
      const items = (definition.sections ?? []).reduce((n, section) => n + section.items.length, 0);
      return { name: q.name, timing: q.timing as "before" | "after", items, instrument: definition.instrument ?? null };
    }),
  );
}

export function assignmentOf(settings: StudySettings): MethodsInput["assignment"] {
  const { strategy, perCondition, stratifyBy } = settings.assignment;
  const question = settings.demographics.find((f) => f.key === stratifyBy);
  return { strategy, perCondition, ...(strategy === "stratified" && question ? { stratifiedBy: question.label } : {}) };
}
