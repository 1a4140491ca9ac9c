// The rows a procedure can act on, each loaded with the study it belongs to.
// The study is always read from the row, never taken from the caller's input.
import { eq, getTableColumns } from "drizzle-orm";
import type { Database } from "@/store/client";
import {
  annotations,
  codeEvents,
  codingSchemeVersions,
  codingSchemes,
  conditions,
  experimentVersions,
  experiments,
  mediaRecordings,
  participants,
  questionnaires,
  sessions,
  studies,
  studyAudio,
  trials,
} from "@/store/schema";

type Db = Pick<Database, "select">;

const LOADERS = {
  study: async (db: Db, id: string) =>
    (
      await db
        .select({ ...getTableColumns(studies), studyId: studies.id })
        .from(studies)
        .where(eq(studies.id, id))
    )[0],
  experiment: async (db: Db, id: string) => (await db.select().from(experiments).where(eq(experiments.id, id)))[0],
  version: async (db: Db, id: string) =>
    (
      await db
        .select({ ...getTableColumns(experimentVersions), studyId: experiments.studyId })
        .from(experimentVersions)
        .innerJoin(experiments, eq(experiments.id, experimentVersions.experimentId))
        .where(eq(experimentVersions.id, id))
    )[0],
  participant: async (db: Db, id: string) => (await db.select().from(participants).where(eq(participants.id, id)))[0],
  trial: async (db: Db, id: string) => (await db.select().from(trials).where(eq(trials.id, id)))[0],
  condition: async (db: Db, id: string) => (await db.select().from(conditions).where(eq(conditions.id, id)))[0],
  recording: async (db: Db, id: string) =>
    (
      await db
        .select({ ...getTableColumns(mediaRecordings), studyId: trials.studyId })
        .from(mediaRecordings)
        .innerJoin(trials, eq(trials.id, mediaRecordings.trialId))
        .where(eq(mediaRecordings.id, id))
    )[0],
  session: async (db: Db, id: string) => (await db.select().from(sessions).where(eq(sessions.id, id)))[0],
  annotation: async (db: Db, id: string) =>
    (
      await db
        .select({ ...getTableColumns(annotations), studyId: trials.studyId })
        .from(annotations)
        .innerJoin(trials, eq(trials.id, annotations.trialId))
        .where(eq(annotations.id, id))
    )[0],
  questionnaire: async (db: Db, id: string) =>
    (await db.select().from(questionnaires).where(eq(questionnaires.id, id)))[0],
  audioFile: async (db: Db, id: string) => (await db.select().from(studyAudio).where(eq(studyAudio.id, id)))[0],
  codingScheme: async (db: Db, id: string) =>
    (await db.select().from(codingSchemes).where(eq(codingSchemes.id, id)))[0],
  schemeVersion: async (db: Db, id: string) =>
    (
      await db
        .select({ ...getTableColumns(codingSchemeVersions), studyId: codingSchemes.studyId })
        .from(codingSchemeVersions)
        .innerJoin(codingSchemes, eq(codingSchemes.id, codingSchemeVersions.schemeId))
        .where(eq(codingSchemeVersions.id, id))
    )[0],
  codeEvent: async (db: Db, id: string) =>
    (
      await db
        .select({ ...getTableColumns(codeEvents), studyId: trials.studyId })
        .from(codeEvents)
        .innerJoin(trials, eq(trials.id, codeEvents.trialId))
        .where(eq(codeEvents.id, id))
    )[0],
} satisfies Record<string, (db: Db, id: string) => Promise<{ studyId: string } | undefined>>;

export type Resource = keyof typeof LOADERS;
export type ResourceRow<R extends Resource> = NonNullable<Awaited<ReturnType<(typeof LOADERS)[R]>>>;

/** What the caller calls each kind of row, for messages. */
const NAMES: Record<Resource, string> = {
  study: "study",
  experiment: "experiment",
  version: "published version",
  participant: "participant",
  trial: "trial",
  condition: "condition",
  recording: "recording",
  session: "session",
  annotation: "annotation",
  questionnaire: "questionnaire",
  audioFile: "audio file",
  codingScheme: "coding scheme",
  schemeVersion: "coding scheme version",
  codeEvent: "code",
};

/**
 * Every input key that names a row, and the kind of row it names. One list:
 * the middleware checks each against the study, and the isolation test swaps
 * each for another study's row. `member` keys name a person who must be a
 * member of the study.
 */
export const REFERENCES = {
  studyId: "study",
  experimentId: "experiment",
  versionId: "version",
  participantId: "participant",
  trialId: "trial",
  conditionId: "condition",
  recordingId: "recording",
  sessionId: "session",
  annotationId: "annotation",
  questionnaireId: "questionnaire",
  audioFileId: "audioFile",
  codingSchemeId: "codingScheme",
  schemeVersionId: "schemeVersion",
  codeEventId: "codeEvent",
  wizardId: "member",
  userId: "member",
} as const satisfies Record<string, Resource | "member">;

export type ReferenceKey = keyof typeof REFERENCES;

/**
 * Input keys that name a row of another study on purpose: the study a copy
 * goes into. The check above leaves them alone; the procedure authorizes each
 * itself, for what it does there (`authorize` in api/trpc.ts), and the
 * isolation test swaps them for another study's rows like every reference.
 */
export const ACROSS_STUDIES = { intoStudyId: "study" } as const satisfies Record<string, Resource>;

/** The input key a procedure acting on this kind of row carries its id in. */
export function keyOf(resource: Resource): ReferenceKey {
  return `${resource}Id` as ReferenceKey;
}

export function nameOf(resource: Resource): string {
  return NAMES[resource];
}

export async function loadResource<R extends Resource>(
  db: Db,
  resource: R,
  id: string,
): Promise<ResourceRow<R> | undefined> {
  return (await LOADERS[resource](db, id)) as ResourceRow<R> | undefined;
}
