// The study's methods text, from the study's rows as they are now: the
// conditions with their latest published protocols, who took part, the robots
// the trials actually ran on (from the trials' own rows, not the experiments'
// plans), each condition's finished trials folded into timings and fidelity,
// questionnaires with their responses, coding agreement. Read by the study
// page's Methods tab and the study zip.
import { and, asc, desc, eq, isNotNull } from "drizzle-orm";
import { studySummary } from "@/core/analysis/study-summary";
import { countedWords } from "@/core/coding/counted";
import { actionNamesOf } from "@/core/designer/action-name";
import { readSnapshot } from "@/core/protocol/snapshot";
import { conditionOfTrial, type EnrolledParticipant, enrolment, type RunTrial } from "@/core/studies/enrolment";
import { type StudyFacts, studyMethodsMarkdown, studyMethodsPlainText } from "@/core/studies/methods";
import { readSettings } from "@/core/studies/settings";
import type { Database } from "@/store/client";
import {
  conditions,
  experimentVersions,
  experiments,
  participants,
  questionnaireLinks,
  robots,
  studies,
  trials,
} from "@/store/schema";
import packageJson from "../../../package.json";
import { studyAgreement } from "../coding/agreement";
import { keptCounted, publishedSchemes } from "../coding/schemes";
import { assignmentOf, givenQuestionnaires, pinnedPlugin } from "../experiments/methods";
import { fileSlug } from "../file-slug";
import { submitted } from "../questionnaires/responses";
import { finishedTrials } from "./summary";

type VersionRow = typeof experimentVersions.$inferSelect;

export async function studyMethodsText(db: Database, studyId: string) {
  const facts = await studyFacts(db, studyId);
  return {
    markdown: studyMethodsMarkdown(facts),
    text: studyMethodsPlainText(facts),
    filename: `${fileSlug(facts.title, "study")}-methods.md`,
  };
}

export async function studyFacts(db: Database, studyId: string): Promise<StudyFacts> {
  const [study] = await db.select().from(studies).where(eq(studies.id, studyId));
  const settings = readSettings(study!.settings);
  const conditionRows = await db
    .select({
      id: conditions.id,
      name: conditions.name,
      description: conditions.description,
      experimentId: conditions.experimentId,
      experiment: experiments.name,
    })
    .from(conditions)
    .innerJoin(experiments, eq(experiments.id, conditions.experimentId))
    .where(eq(conditions.studyId, studyId))
    .orderBy(asc(conditions.name));
  const experimentOf = new Map(conditionRows.map((c) => [c.id, c.experimentId]));
  const people: EnrolledParticipant[] = (
    await db
      .select({
        id: participants.id,
        consentStatus: participants.consentStatus,
        conditionId: participants.conditionId,
        conditionOrder: participants.conditionOrder,
      })
      .from(participants)
      .where(eq(participants.studyId, studyId))
  ).map((p) => ({
    id: p.id,
    consentStatus: p.consentStatus,
    conditionIds: p.conditionId
      ? [p.conditionId]
      : Array.isArray(p.conditionOrder)
        ? (p.conditionOrder as string[])
        : [],
  }));
  const runs = await db
    .select({
      id: trials.id,
      participantId: trials.participantId,
      experimentId: trials.experimentId,
      status: trials.status,
      t0: trials.t0,
      version: experimentVersions,
      robot: { name: robots.name, simulated: robots.simulated },
    })
    .from(trials)
    .innerJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
    .leftJoin(robots, eq(robots.id, trials.assignedRobotId))
    .where(and(eq(trials.studyId, studyId), eq(trials.isRehearsal, false), isNotNull(trials.participantId)));
  const trialRows: RunTrial[] = runs.map((t) => ({ ...t, participantId: t.participantId! }));
  const byId = new Map(people.map((p) => [p.id, p]));
  const figures = await finishedTrials(db, studyId);
  const trialOf = new Map(trialRows.map((t) => [t.id, t]));
  const figuresOf = (conditionId: string) =>
    figures.filter((f) => {
      const t = trialOf.get(f.trialId);
      return t && conditionOfTrial(t, byId, experimentOf) === conditionId;
    });
  const [answers, questionnaires, schemes] = await Promise.all([
    submitted(db, eq(questionnaireLinks.studyId, studyId)),
    givenQuestionnaires(db, studyId),
    publishedSchemes(db, studyId),
  ]);
  return {
    title: study!.title,
    conditions: await Promise.all(
      conditionRows.map(async (c) => {
        const summary = studySummary(figuresOf(c.id));
        return {
          name: c.name,
          description: c.description,
          experiment: c.experiment,
          protocol: await latestProtocol(db, c.experimentId),
          ...enrolment(c.id, people, trialRows, experimentOf),
          steps: summary.steps.map(({ name, durationMs }) => ({ name, durationMs })),
          fidelity: {
            trials: summary.consistency.trials,
            meanFidelity: summary.consistency.meanFidelity,
            sdFidelity: summary.consistency.sdFidelity,
            withoutDeviation: summary.consistency.withoutDeviation,
            deviationsByKind: summary.consistency.deviationsByKind,
          },
        };
      }),
    ),
    assignment: { ...assignmentOf(settings), seed: settings.assignment.seed ?? null },
    blinding: settings.blinding,
    robots: await robotsUsed(
      db,
      // The trials that ran (a scheduled one has not), of participants who have not withdrawn.
      runs.filter((t) => t.t0 && byId.get(t.participantId!)?.consentStatus !== "withdrawn"),
    ),
    questionnaires: questionnaires.map((q) => ({
      ...q,
      responses: answers.filter((a) => a.questionnaire === q.name).length,
    })),
    coding: await Promise.all(
      schemes.map(async (scheme) => {
        // Counted as the scheme keeps it, as the Results tab shows it.
        const counted = await keptCounted(db, scheme.schemeId);
        const found = await studyAgreement(db, studyId, scheme.versionId, scheme.definition, counted);
        const nameOf = (id: string) => found.observers.find((o) => o.id === id)!.name;
        return {
          name: scheme.definition.name,
          version: scheme.version,
          counted: countedWords(counted, found.steps),
          sets: found.sets.map((set) => ({
            name: set.name,
            pairs: found.pairs.map((pair) => {
              const pooled = pair.pooled.find((p) => p.setId === set.id)!;
              return {
                observers: [nameOf(pair.a), nameOf(pair.b)] as [string, string],
                kappa: pooled.kappa,
                slices: pooled.n,
              };
            }),
          })),
        };
      }),
    ),
    software: { version: packageJson.version },
  };
}

async function latestProtocol(
  db: Database,
  experimentId: string,
): Promise<StudyFacts["conditions"][number]["protocol"]> {
  const [version] = await db
    .select()
    .from(experimentVersions)
    .where(eq(experimentVersions.experimentId, experimentId))
    .orderBy(desc(experimentVersions.version))
    .limit(1);
  if (!version) return null;
  const plugin = await pinnedPlugin(db, version);
  return {
    version: version.version,
    hash: version.hash,
    snapshot: readSnapshot(version.snapshot),
    names: actionNamesOf(plugin),
    events: plugin?.events,
  };
}

/** Each robot and plugin document the trials ran with, counted; a trial with no robot recorded says so. */
async function robotsUsed(
  db: Database,
  runs: Array<{ version: VersionRow; robot: { name: string; simulated: boolean } | null }>,
): Promise<StudyFacts["robots"]> {
  const plugins = new Map<string, string>();
  const used = new Map<string, StudyFacts["robots"][number]>();
  for (const { version, robot } of runs) {
    if (!plugins.has(version.id)) plugins.set(version.id, (await pinnedPlugin(db, version))?.name ?? version.robotId);
    const key = JSON.stringify([robot?.name, version.pluginHash, version.pluginVersion, version.robotId]);
    const entry = used.get(key) ?? {
      name: robot?.name ?? "a robot not recorded with the trial",
      simulated: robot?.simulated ?? null,
      plugin: plugins.get(version.id)!,
      pluginVersion: version.pluginVersion,
      pluginHash: version.pluginHash,
      trials: 0,
    };
    entry.trials++;
    used.set(key, entry);
  }
  return [...used.values()].sort((a, b) => a.name.localeCompare(b.name));
}
