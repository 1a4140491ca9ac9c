// A trial as files: its events as tidy CSV, its full record as JSON (the
// protocol version embedded, events, annotations, questionnaires,
// recordings, codes), its codes as tidy CSV, or an ELAN document for video coding. The trial's download
// and the study's archive both take them from here, reading the trial once.
import { asc, eq } from "drizzle-orm";
import { elanDocument } from "@/core/analysis/elan";
import { tableCsv, tableRecords } from "@/core/analysis/table";
import { codesTable } from "@/core/coding/export";
import { eventsCsv, trialRecordJson } from "@/core/analysis/exports";
import { trialNames } from "@/core/analysis/names";
import type { TrialEvent } from "@/core/trial";
import type { Database } from "@/store/client";
import { annotations, experimentVersions, mediaRecordings, questionnaireLinks, trials, user } from "@/store/schema";
import { codeRowsOf } from "../coding/rows";
import { recordingFileName } from "../media/recordings";
import { submitted } from "../questionnaires/responses";
import { eventsSince } from "@/store/event-store";
import { trialActionNames } from "./action-names";

export type TrialFormat = "csv" | "json" | "eaf" | "codes";

/** The name of an account, or null (none given, or the account was deleted). */
async function nameOf(db: Database, userId: string | null) {
  if (!userId) return null;
  const [person] = await db.select({ name: user.name }).from(user).where(eq(user.id, userId));
  return person?.name ?? null;
}

/** What a trial's events need to be read: the trial, its people, its protocol and the names of its actions. */
export async function trialEventsOf(db: Database, trialId: string) {
  const [trial] = await db.select().from(trials).where(eq(trials.id, trialId));
  const [version] = trial!.versionId
    ? await db.select().from(experimentVersions).where(eq(experimentVersions.id, trial!.versionId))
    : [];
  const protocol = version?.snapshot ?? trial!.rehearsalSnapshot;
  // Every trial runs a published version or, for a rehearsal, the draft frozen when it began.
  if (!protocol) throw new Error(`Trial ${trial!.id} has neither a version nor a rehearsal snapshot`);
  return {
    trial: trial!,
    // Who ran it and who created it: two named fields, as the trial page shows them.
    people: { wizard: await nameOf(db, trial!.wizardId), createdBy: await nameOf(db, trial!.createdBy) },
    version,
    protocol,
    events: await eventsSince(db, trialId),
    names: await trialActionNames(db, trialId),
  };
}

async function readTrial(db: Database, trialId: string) {
  return {
    ...(await trialEventsOf(db, trialId)),
    marked: await db
      .select({ relMs: annotations.relMs, label: annotations.label, note: annotations.note, authorName: user.name })
      .from(annotations)
      .leftJoin(user, eq(user.id, annotations.authorId))
      .where(eq(annotations.trialId, trialId))
      .orderBy(asc(annotations.relMs)),
    recordings: await db
      .select()
      .from(mediaRecordings)
      .where(eq(mediaRecordings.trialId, trialId))
      .orderBy(asc(mediaRecordings.createdAt)),
    questionnaires: await submitted(db, eq(questionnaireLinks.trialId, trialId)),
    codes: await codeRowsOf(db, [trialId]),
  };
}

function fileOf(
  {
    trial,
    people,
    version,
    protocol,
    events,
    marked,
    recordings,
    questionnaires,
    names,
    codes,
  }: Awaited<ReturnType<typeof readTrial>>,
  format: TrialFormat,
) {
  const name = `trial-${trial.id}`;
  const named = trialNames(protocol, events, names);
  if (format === "csv")
    return {
      filename: `${name}-events.csv`,
      contentType: "text/csv; charset=utf-8",
      body: eventsCsv(trial.id, events, people, named),
    };
  if (format === "codes")
    return { filename: `${name}-codes.csv`, contentType: "text/csv; charset=utf-8", body: tableCsv(codesTable(codes)) };
  if (format === "eaf") {
    const video = recordings.find((r) => r.status === "complete" && r.kind === "video");
    const media = video
      ? {
          fileName: recordingFileName(video.id, video.mimeType),
          mimeType: video.mimeType,
          offsetMs: video.offsetMs ?? 0,
        }
      : undefined;
    const body = elanDocument({
      protocol,
      events: events as unknown as TrialEvent[],
      annotations: marked,
      date: (trial.t0 ?? trial.createdAt).toISOString(),
      media,
      names,
      codes,
    });
    return { filename: `${name}.eaf`, contentType: "application/xml; charset=utf-8", body };
  }
  const record = trialRecordJson(
    {
      trial: {
        ...trial,
        wizardName: people.wizard,
        createdByName: people.createdBy,
        rehearsalSnapshot: undefined,
        version: version
          ? {
              id: version.id,
              number: version.version,
              hash: version.hash,
              robotId: version.robotId,
              pluginVersion: version.pluginVersion,
            }
          : null,
      },
      protocol,
      events,
      annotations: marked,
      questionnaires,
      recordings: recordings.map((m) => ({
        id: m.id,
        kind: m.kind,
        mimeType: m.mimeType,
        status: m.status,
        sizeBytes: m.sizeBytes,
        offsetMs: m.offsetMs,
        durationMs: m.durationMs,
        url: `/api/recordings/${m.id}/media`,
      })),
      codes: tableRecords(codesTable(codes)),
    },
    named,
  );
  return { filename: `${name}.json`, contentType: "application/json", body: record };
}

export async function trialFile(db: Database, trialId: string, format: TrialFormat) {
  return fileOf(await readTrial(db, trialId), format);
}

/** Several formats of one trial from one reading of it (the study archive's case). */
export async function trialFiles(db: Database, trialId: string, formats: TrialFormat[]) {
  const data = await readTrial(db, trialId);
  return formats.map((format) => fileOf(data, format));
}
