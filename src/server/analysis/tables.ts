// The analysis API's tables of a study, read from the same rows and with the
// same builders as the exports: a trial's events as in its events CSV,
// answers as in questionnaire-answers.csv.
import { codesTable as tableOfCodes } from "@/core/coding/export";
import { codeRowsOf } from "../coding/rows";
import { and, asc, eq, inArray, ne } from "drizzle-orm";
import { ANNOTATION_COLUMNS, TRIAL_COLUMNS } from "@/core/analysis/api";
import { EVENT_COLUMNS, eventRows, SAMPLE_COLUMNS } from "@/core/analysis/exports";
import { trialNames } from "@/core/analysis/names";
import { type Table, tableOf } from "@/core/analysis/table";
import { ANSWER_COLUMNS, answerRows } from "@/core/questionnaires/export";
import type { Database } from "@/store/client";
import {
  annotations,
  conditions,
  experimentVersions,
  experiments,
  participants,
  questionnaireLinks,
  trials,
  user,
} from "@/store/schema";
import { samplesOfTrials } from "@/store/samples";
import { submitted } from "../questionnaires/responses";
import { trialsEventsOf } from "../trials/files";

/**
 * The trials a study's data is made of, oldest first: the archive's rule, no
 * rehearsals and no participant who withdrew. A trial's condition is its
 * participant's, as in the results by condition.
 */
export function analysedTrials(db: Database, studyId: string) {
  return db
    .select({
      id: trials.id,
      experiment: experiments.name,
      version: experimentVersions.version,
      participant: participants.code,
      condition: conditions.name,
      wizard: user.name,
      status: trials.status,
      t0: trials.t0,
      endedAt: trials.endedAt,
    })
    .from(trials)
    .innerJoin(experiments, eq(experiments.id, trials.experimentId))
    .leftJoin(experimentVersions, eq(experimentVersions.id, trials.versionId))
    .innerJoin(participants, eq(participants.id, trials.participantId))
    .leftJoin(conditions, eq(conditions.id, participants.conditionId))
    .leftJoin(user, eq(user.id, trials.wizardId))
    .where(and(eq(trials.studyId, studyId), eq(trials.isRehearsal, false), ne(participants.consentStatus, "withdrawn")))
    .orderBy(asc(trials.createdAt));
}

const ids = async (db: Database, studyId: string) => (await analysedTrials(db, studyId)).map((t) => t.id);

export async function trialsTable(db: Database, studyId: string): Promise<Table> {
  const rows = await analysedTrials(db, studyId);
  return tableOf(
    TRIAL_COLUMNS,
    rows.map((t) => ({
      trial_id: t.id,
      experiment: t.experiment,
      version: t.version,
      participant: t.participant,
      condition: t.condition,
      wizard: t.wizard,
      status: t.status,
      started_at: t.t0?.toISOString(),
      ended_at: t.endedAt?.toISOString(),
      duration_ms: t.t0 && t.endedAt ? t.endedAt.getTime() - t.t0.getTime() : null,
    })),
  );
}

/** Every event of these trials, each trial's in order, in its events CSV's columns: one read for them all. */
export async function eventsTable(db: Database, trialIds: string[]): Promise<Table> {
  const rows = [];
  for (const { trial, people, protocol, events, names } of await trialsEventsOf(db, trialIds))
    for (const row of eventRows(trial.id, events, people, trialNames(protocol, events, names))) rows.push(row);
  return { columns: EVENT_COLUMNS, rows };
}

export const studyEventsTable = async (db: Database, studyId: string) => eventsTable(db, await ids(db, studyId));

export async function samplesTable(db: Database, studyId: string): Promise<Table> {
  const trialIds = await ids(db, studyId);
  const rows = await samplesOfTrials(db, trialIds);
  return tableOf(
    SAMPLE_COLUMNS,
    rows.map((s) => ({ trial_id: s.trialId, topic: s.topic, rel_ms: s.relMs, data: JSON.stringify(s.data) })),
  );
}

export async function answersTable(db: Database, studyId: string): Promise<Table> {
  return { columns: ANSWER_COLUMNS, rows: answerRows(await submitted(db, eq(questionnaireLinks.studyId, studyId))) };
}

export async function annotationsTable(db: Database, studyId: string): Promise<Table> {
  const trialIds = await ids(db, studyId);
  const rows = trialIds.length
    ? await db
        .select({
          trialId: annotations.trialId,
          relMs: annotations.relMs,
          label: annotations.label,
          note: annotations.note,
          author: user.name,
        })
        .from(annotations)
        .leftJoin(user, eq(user.id, annotations.authorId))
        .where(inArray(annotations.trialId, trialIds))
        .orderBy(asc(annotations.trialId), asc(annotations.relMs))
    : [];
  return tableOf(
    ANNOTATION_COLUMNS,
    rows.map((a) => ({ trial_id: a.trialId, rel_ms: a.relMs, label: a.label, note: a.note, author: a.author })),
  );
}

export async function codesTable(db: Database, studyId: string): Promise<Table> {
  return tableOfCodes(await codeRowsOf(db, await ids(db, studyId)));
}
