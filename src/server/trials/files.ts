// A trial as files: its events as tidy CSV, its full record as JSON (the
// protocol version embedded, events, annotations, questionnaires,
// recordings, robot state samples, codes), its robot state samples or its
// codes as tidy CSV, an ELAN document for video coding (codes included), or
// an MCAP file for robotics tools. The trial's download
// and the study's archive both take them from here, reading the trial once:
// the archive a batch of trials whole, the trial's events CSV and record a
// page of rows at a time (the same bytes), as the download is written.
import { asc, inArray } from "drizzle-orm";
import { elanDocument } from "@/core/analysis/elan";
import {
  type Batches,
  EVENT_COLUMNS,
  eventRows,
  eventsCsv,
  namedEvents,
  samplesCsv,
  trialRecordJson,
  trialRecordPieces,
} from "@/core/analysis/exports";
import { csvLines } from "@/core/csv/csv";
import { tableCsv, tableRecords } from "@/core/analysis/table";
import { codesTable } from "@/core/coding/export";
import { trialNames } from "@/core/analysis/names";
import type { StoredEvent, TrialEvent } from "@/core/trial";
import type { Database } from "@/store/client";
import { experimentVersions, mediaRecordings, questionnaireLinks, trials, user } from "@/store/schema";
import { recordingFileName } from "../media/recordings";
import { submitted, submittedPages } from "../questionnaires/responses";
import { eventPages, eventsOfTrials, lastSeqOf } from "@/store/event-store";
import { lastSampleOf, samplePages, samplesOfTrials } from "@/store/samples";
import type { ActionNames } from "@/core/designer/action-name";
import { trialPlugin } from "@/robots/trial-plugin";
import { inCondition } from "@/core/protocol/variants";
import { conditionsOfTrials } from "@/store/trial-condition";
import { trialActionNames } from "./action-names";
import { annotationPages, annotationsOf } from "./annotations";
import { trialMcap } from "./mcap";
import { textStream } from "./text-stream";
import { codePages, codeRowsOf } from "../coding/rows";

export type TrialFormat = "csv" | "json" | "eaf" | "samples" | "codes";

/** The names of these accounts by id (an account deleted since has none). */
async function namesOf(db: Database, userIds: (string | null)[]) {
  const wanted = [...new Set(userIds.filter((id): id is string => id !== null))];
  const rows = wanted.length
    ? await db.select({ id: user.id, name: user.name }).from(user).where(inArray(user.id, wanted))
    : [];
  return new Map(rows.map((r) => [r.id, r.name]));
}

/** Each row of `rows` under its trial, for a batch read in one query. */
function byTrial<T extends { trialId: string | null }>(trialIds: string[], rows: T[]) {
  const grouped = new Map<string, T[]>(trialIds.map((id) => [id, []]));
  for (const row of rows) if (row.trialId) grouped.get(row.trialId)?.push(row);
  return grouped;
}

/**
 * What these trials' events need to be read: each trial, its people, its
 * protocol and the names of its actions. One query per kind of row for the
 * whole batch (not per trial), so a study of 1,000 trials costs a handful of
 * queries per batch; the action names are looked up once per version.
 */
async function trialsOf(db: Database, trialIds: string[]) {
  if (!trialIds.length) return [];
  const trialRows = await db.select().from(trials).where(inArray(trials.id, trialIds));
  const versionIds = [...new Set(trialRows.flatMap((t) => (t.versionId ? [t.versionId] : [])))];
  const versions = versionIds.length
    ? await db.select().from(experimentVersions).where(inArray(experimentVersions.id, versionIds))
    : [];
  const people = await namesOf(
    db,
    trialRows.flatMap((t) => [t.wizardId, t.createdBy]),
  );
  const conditionOf = await conditionsOfTrials(
    db,
    trialRows.filter((t) => !t.isRehearsal).map((t) => t.id),
  );
  const namesByRun = new Map<string, Promise<ActionNames>>();
  const order = new Map(trialIds.map((id, i) => [id, i]));
  return Promise.all(
    trialRows
      .sort((a, b) => order.get(a.id)! - order.get(b.id)!)
      .map(async (trial) => {
        const version = versions.find((v) => v.id === trial.versionId);
        const stored = version?.snapshot ?? trial.rehearsalSnapshot;
        // Every trial runs a published version or, for a rehearsal, the draft frozen when it began.
        if (!stored) throw new Error(`Trial ${trial.id} has neither a version nor a rehearsal snapshot`);
        // As its condition ran it: each action of a condition's variant names the condition (the version's hash keeps them all).
        const protocol = inCondition(stored, conditionOf.get(trial.id) ?? null);
        // Trials of one version run with one plugin document: its names are read once.
        const run = trial.versionId ?? `draft:${trial.experimentId}`;
        if (!namesByRun.has(run)) namesByRun.set(run, trialActionNames(db, trial.id));
        return {
          trial,
          // Who ran it and who created it: two named fields, as the trial page shows them.
          people: {
            wizard: (trial.wizardId && people.get(trial.wizardId)) ?? null,
            createdBy: (trial.createdBy && people.get(trial.createdBy)) ?? null,
          },
          version,
          protocol,
          names: await namesByRun.get(run)!,
        };
      }),
  );
}

/** These trials as trialsOf reads them, each with all its events. */
export async function trialsEventsOf(db: Database, trialIds: string[]) {
  const [read, events] = await Promise.all([trialsOf(db, trialIds), eventsOfTrials(db, trialIds)]);
  return read.map((r) => ({ ...r, events: events.get(r.trial.id)! }));
}

/** These trials' recordings, by trial, in the order they were made. */
async function recordingsOf(db: Database, trialIds: string[]) {
  return trialIds.length
    ? db
        .select()
        .from(mediaRecordings)
        .where(inArray(mediaRecordings.trialId, trialIds))
        .orderBy(asc(mediaRecordings.createdAt))
    : [];
}

/** What these trials' files hold besides their events, by trial: one query per kind of row. */
async function besidesEvents(db: Database, trialIds: string[]) {
  const [marked, recordings, questionnaires, samples, codes] = await Promise.all([
    annotationsOf(db, trialIds),
    recordingsOf(db, trialIds),
    trialIds.length ? submitted(db, inArray(questionnaireLinks.trialId, trialIds)) : [],
    samplesOfTrials(db, trialIds),
    codeRowsOf(db, trialIds),
  ]);
  const markedBy = byTrial(trialIds, marked);
  const recordingsBy = byTrial(trialIds, recordings);
  const questionnairesBy = byTrial(trialIds, questionnaires);
  const samplesBy = byTrial(trialIds, samples);
  const codesBy = byTrial(trialIds, codes);
  return (trialId: string) => ({
    marked: markedBy.get(trialId)!.map(({ trialId: _, id: _id, ...a }) => a),
    recordings: recordingsBy.get(trialId)!,
    questionnaires: questionnairesBy.get(trialId)!,
    samples: samplesBy.get(trialId)!.map(({ trialId: _, ...sample }) => sample),
    codes: codesBy.get(trialId)!,
  });
}

/** Everything of these trials that their files hold, read in one query per kind of row. */
export async function readTrials(db: Database, trialIds: string[]) {
  const [read, besides] = await Promise.all([trialsEventsOf(db, trialIds), besidesEvents(db, trialIds)]);
  return read.map((r) => ({ ...r, ...besides(r.trial.id) }));
}

type ReadTrial = Awaited<ReturnType<typeof readTrials>>[number];

/** The events CSV's and the record's names and types, whole (the archive's) or streamed (the trial's download). */
const FILES = {
  csv: { suffix: "-events.csv", contentType: "text/csv; charset=utf-8" },
  json: { suffix: ".json", contentType: "application/json" },
};

function fileOf(read: ReadTrial, format: TrialFormat) {
  const { trial, people, protocol, events, marked, recordings, names, samples, codes } = read;
  const name = `trial-${trial.id}`;
  const named = trialNames(protocol, events, names);
  if (format === "csv")
    return {
      filename: name + FILES.csv.suffix,
      contentType: FILES.csv.contentType,
      body: eventsCsv(trial.id, events, people, named),
    };
  if (format === "samples")
    return {
      filename: `${name}-samples.csv`,
      contentType: "text/csv; charset=utf-8",
      body: samplesCsv(trial.id, samples),
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
  return {
    filename: name + FILES.json.suffix,
    contentType: FILES.json.contentType,
    body: trialRecordJson(
      {
        ...recordOf(read, recordings),
        events,
        annotations: marked,
        questionnaires: read.questionnaires,
        samples,
        codes: tableRecords(codesTable(codes)),
      },
      named,
    ),
  };
}

/** The trial record's parts that are not lists of rows (see TrialRecord): its trial, protocol and recordings. */
function recordOf(
  { trial, people, version, protocol }: Awaited<ReturnType<typeof trialsOf>>[number],
  recordings: Awaited<ReturnType<typeof recordingsOf>>,
) {
  return {
    trial: {
      ...trial,
      wizardName: people.wizard,
      createdByName: people.createdBy,
      rehearsalSnapshot: undefined,
      // How many runtime processes took the trial: the runtime's bookkeeping, not the study's record.
      ownerEpoch: undefined,
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
  };
}

/** Each page of `pages` as `made` makes it. */
async function* mapped<T, U>(pages: Batches<T>, made: (page: T[]) => U[]): Batches<U> {
  for await (const page of pages) yield made(page);
}

/** How many rows (events, samples…) a streamed file reads at a time (and one more page ahead): its memory bound. */
export const ROWS_PER_READ = 5000;

/**
 * The trial's events CSV or its record as JSON, written as its rows are read,
 * a page at a time (the same bytes as the study archive's copy of them): a
 * trial of 100k events or 180k robot state samples never sits in the
 * server's memory whole. The events are read once: each page's requests name
 * its unscripted actions before its events are named (see trialNames).
 */
async function streamedFile(db: Database, trialId: string, format: "csv" | "json") {
  // The file holds the log (and the samples) as they stood when the download began: what a live
  // trial adds later is in neither the events nor the names of the file.
  const [upTo, lastSample, [read], recordings] = await Promise.all([
    lastSeqOf(db, trialId),
    format === "json" ? lastSampleOf(db, trialId) : 0,
    trialsOf(db, [trialId]),
    format === "json" ? recordingsOf(db, [trialId]) : [],
  ]);
  const { trial, people, protocol, names } = read!;
  const named = trialNames(protocol, [], names);
  const events = <T>(made: (events: StoredEvent[]) => T[]) =>
    mapped(eventPages(db, trialId, { limit: ROWS_PER_READ, upTo }), (page) => {
      named.learn(page);
      return made(page);
    });
  async function* csv() {
    yield csvLines([EVENT_COLUMNS]);
    for await (const rows of events((page) => eventRows(trial.id, page, people, named))) yield csvLines(rows);
  }
  // Each list is read only once the one before it is written.
  const record = () =>
    trialRecordPieces({
      ...recordOf(read!, recordings),
      events: events((page) => namedEvents(page, named)),
      annotations: mapped(annotationPages(db, trialId, ROWS_PER_READ), (page) =>
        page.map(({ trialId: _, id: _id, ...a }) => a),
      ),
      questionnaires: mapped(submittedPages(db, trialId, ROWS_PER_READ), (page) =>
        page.map(({ responseId: _, ...q }) => q),
      ),
      samples: mapped(samplePages(db, trialId, { limit: ROWS_PER_READ, upTo: lastSample }), (page) =>
        page.map(({ id: _, ...sample }) => sample),
      ),
      codes: mapped(codePages(db, trialId, ROWS_PER_READ), (page) => tableRecords(codesTable(page))),
    });
  return {
    filename: `trial-${trial.id}${FILES[format].suffix}`,
    contentType: FILES[format].contentType,
    body: textStream(
      format === "csv" ? csv() : record(),
      `The ${format === "csv" ? "events CSV" : "record"} of trial ${trial.id}`,
    ),
  };
}

export async function trialFile(db: Database, trialId: string, format: TrialFormat | "mcap") {
  if (format === "csv" || format === "json") return streamedFile(db, trialId, format);
  const [read] = await readTrials(db, [trialId]);
  if (format !== "mcap") return fileOf(read!, format);
  const { trial, events, samples } = read!;
  const chosen = await trialPlugin(db, trialId);
  const stateTopics = (chosen.ok && chosen.plugin?.stateTopics) || [];
  const rosTypes = new Map(stateTopics.map((t) => [t.topic, t.messageType]));
  return {
    filename: `trial-${trial.id}.mcap`,
    contentType: "application/octet-stream",
    body: new Uint8Array(
      await trialMcap({ trialId: trial.id, t0: trial.t0 ?? trial.createdAt, events, samples, rosTypes }),
    ),
  };
}

/** Several formats of each of these trials, from one batch read of them (the study archive's case). */
export async function trialsFiles(db: Database, trialIds: string[], formats: TrialFormat[]) {
  return (await readTrials(db, trialIds)).map((read) => ({
    trialId: read.trial.id,
    files: formats.map((format) => fileOf(read, format)),
  }));
}
