// Which study an input points at, and the caller's role in it.
import { TRPCError } from "@trpc/server";
import { and, eq } from "drizzle-orm";
import { isStudyOperation, type Operation, type StudyRole } from "@/core/access/policy";
import { blindingFor, NOT_BLINDED, type Blinding } from "@/core/studies/blinding";
import { readSettings } from "@/core/studies/settings";
import type { Database } from "../db/client";
import {
  actions,
  annotations,
  conditions,
  experimentVersions,
  experiments,
  mediaRecordings,
  participants,
  questionnaires,
  sessions,
  steps,
  studies,
  studyMembers,
  trials,
} from "../db/schema";

type Lookup = (db: Database, id: string) => Promise<string | undefined>;

// Each id an input may carry, and how to find its study. The first key present wins.
const LOOKUPS: Array<[string, Lookup]> = [
  ["studyId", async (_db, id) => id],
  // Before participantId and trialId: a link is checked against the questionnaire's own study.
  [
    "questionnaireId",
    async (db, id) => (await db.select({ s: questionnaires.studyId }).from(questionnaires).where(eq(questionnaires.id, id)))[0]?.s,
  ],
  [
    "experimentId",
    async (db, id) =>
      (await db.select({ s: experiments.studyId }).from(experiments).where(eq(experiments.id, id)))[0]?.s,
  ],
  [
    "versionId",
    async (db, id) =>
      (
        await db
          .select({ s: experiments.studyId })
          .from(experimentVersions)
          .innerJoin(experiments, eq(experiments.id, experimentVersions.experimentId))
          .where(eq(experimentVersions.id, id))
      )[0]?.s,
  ],
  [
    "stepId",
    async (db, id) =>
      (
        await db
          .select({ s: experiments.studyId })
          .from(steps)
          .innerJoin(experiments, eq(experiments.id, steps.experimentId))
          .where(eq(steps.id, id))
      )[0]?.s,
  ],
  [
    "actionId",
    async (db, id) =>
      (
        await db
          .select({ s: experiments.studyId })
          .from(actions)
          .innerJoin(steps, eq(steps.id, actions.stepId))
          .innerJoin(experiments, eq(experiments.id, steps.experimentId))
          .where(eq(actions.id, id))
      )[0]?.s,
  ],
  [
    "participantId",
    async (db, id) =>
      (await db.select({ s: participants.studyId }).from(participants).where(eq(participants.id, id)))[0]?.s,
  ],
  [
    "trialId",
    async (db, id) => (await db.select({ s: trials.studyId }).from(trials).where(eq(trials.id, id)))[0]?.s,
  ],
  [
    "conditionId",
    async (db, id) => (await db.select({ s: conditions.studyId }).from(conditions).where(eq(conditions.id, id)))[0]?.s,
  ],
  [
    "recordingId",
    async (db, id) =>
      (await db.select({ s: trials.studyId }).from(mediaRecordings).innerJoin(trials, eq(trials.id, mediaRecordings.trialId)).where(eq(mediaRecordings.id, id)))[0]?.s,
  ],
  [
    "sessionId",
    async (db, id) => (await db.select({ s: sessions.studyId }).from(sessions).where(eq(sessions.id, id)))[0]?.s,
  ],
  [
    "annotationId",
    async (db, id) =>
      (
        await db
          .select({ s: trials.studyId })
          .from(annotations)
          .innerJoin(trials, eq(trials.id, annotations.trialId))
          .where(eq(annotations.id, id))
      )[0]?.s,
  ],
];

export const STUDY_KEYS = LOOKUPS.map(([key]) => key);

export async function studyIdForInput(db: Database, input: unknown, op: Operation): Promise<string | null> {
  if (!isStudyOperation(op)) return null;
  const record = (input && typeof input === "object" ? input : {}) as Record<string, unknown>;
  for (const [key, lookup] of LOOKUPS) {
    const value = record[key];
    if (value === undefined) continue;
    if (typeof value !== "string" || value.length === 0 || value.length > 100) {
      throw new TRPCError({ code: "BAD_REQUEST", message: `Please correct: ${key}: must be an id` });
    }
    const studyId = await lookup(db, value);
    // An unknown id reads exactly like a study the caller may not see.
    if (!studyId) throw new TRPCError({ code: "NOT_FOUND", message: "Study not found." });
    return studyId;
  }
  throw new TRPCError({ code: "INTERNAL_SERVER_ERROR", message: `Operation ${op} needs one of ${STUDY_KEYS.join(", ")}.` });
}

/** The caller's role in a study, and what that study's blinds hide from them. */
export async function studyAccessOf(db: Database, studyId: string, userId: string): Promise<{ role: StudyRole | null; blinding: Blinding }> {
  const [row] = await db
    .select({ role: studyMembers.role, settings: studies.settings, status: studies.status })
    .from(studies)
    .leftJoin(studyMembers, and(eq(studyMembers.studyId, studies.id), eq(studyMembers.userId, userId)))
    .where(eq(studies.id, studyId));
  const role = row?.role ?? null;
  return { role, blinding: row ? blindingFor(role, readSettings(row.settings), row.status) : NOT_BLINDED };
}
