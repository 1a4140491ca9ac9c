// The whole study as one zip: its design and settings, every trial's record
// and events, and every questionnaire answer. What a lab archives or shares
// with a paper. Withdrawn participants' data is left out.
//
// The zip is streamed as it is made: the study's own files first, then the
// trials a batch at a time (a few queries per batch, not per trial), each
// batch read only when the reader has taken the last one. So the first byte
// leaves at once and memory holds one batch, whatever the study's size.
import { strToU8, Zip, ZipDeflate } from "fflate";
import { and, asc, count, eq, inArray, ne } from "drizzle-orm";
import type { Database } from "@/store/client";
import { logUnexpected } from "@/store/error-reference";
import {
  conditions,
  experimentVersions,
  experiments,
  participants,
  questionnaireLinks,
  sessions,
  studies,
  trialEvents,
  trialSamples,
} from "@/store/schema";
import { answersCsv } from "@/core/questionnaires/export";
import { codebookCsv } from "@/core/analysis/codebook";
import { methodsText } from "../experiments/methods";
import { studyMethodsText } from "./methods";
import { fileSlug } from "../file-slug";
import { submitted } from "../questionnaires/responses";
import { tableCsv } from "@/core/analysis/table";
import { codesTable } from "@/core/coding/export";
import { codeRowsOf } from "../coding/rows";
import { trialsFiles } from "../trials/files";
import { analysedTrials } from "../analysis/tables";

const README = `HRIStudio study archive

study.json                  the study, its settings (assignment seed included), conditions,
                            participants (codes, consent, demographics, assignment),
                            experiments with every published version, and sessions
methods.md                  the whole study described for a paper's methods section, from its
                            data when the zip was made: design, n per condition, assignment and
                            seed, blinding, robots the trials ran on, how the conditions' protocols
                            differ, step timings, questionnaires, coding agreement, fidelity
experiments/<name>-v<N>-methods.md
                            each published version described for a paper's methods section:
                            robot and plugin version, steps, exact speech, branches, pauses,
                            questionnaires, conditions and assignment, the version's hash
trials/<id>.json            each trial's full record: protocol version, events,
                            annotations, questionnaires, robot state samples, codes
trials/<id>-events.csv      each trial's events, one row per event (RFC 4180)
trials/<id>-samples.csv     each trial's robot state samples (joint states, battery...), one row per
                            sample: trial_id, topic, rel_ms, data (the message as JSON)
trials/<id>.eaf             each trial as an ELAN document: steps, actions, deviations, annotations,
                            and one tier per observer per set of codes
codes.csv                   every observer's codes: one row per code event (observer, scheme,
                            set, code, start and end in ms from the trial's start, modifiers)
questionnaire-answers.csv   every submitted answer: one row per participant x item (condition,
                            instrument, sub-scale, reverse-scored), then the published scores
codebook.csv                every column of these CSV files: type, unit, allowed values, meaning

Rehearsals are not included. Participants who withdrew are left out, as are their trials
and answers; study.json says how many.
`;

/** A batch of trials is cut once it holds this many rows, events and samples (or trials): the archive's memory bound. */
const BATCH_ROWS = 20_000;
const BATCH_TRIALS = 50;

/** The trials in batches of about BATCH_ROWS rows, in the order given (a large trial is a batch of its own). */
export function batchesOf(trials: { id: string; rows: number }[]) {
  const batches: string[][] = [];
  let batch: string[] = [];
  let rows = 0;
  for (const trial of trials) {
    if (batch.length && (rows + trial.rows > BATCH_ROWS || batch.length === BATCH_TRIALS)) {
      batches.push(batch);
      batch = [];
      rows = 0;
    }
    batch.push(trial.id);
    rows += trial.rows;
  }
  if (batch.length) batches.push(batch);
  return batches;
}

/** The study's own files: README, study.json, methods texts and questionnaire answers. */
async function studyFiles(db: Database, studyId: string) {
  const [study] = await db.select().from(studies).where(eq(studies.id, studyId));
  const people = await db
    .select()
    .from(participants)
    .where(eq(participants.studyId, studyId))
    .orderBy(asc(participants.code));
  const kept = people.filter((p) => p.consentStatus !== "withdrawn");
  const conditionRows = await db
    .select()
    .from(conditions)
    .where(eq(conditions.studyId, studyId))
    .orderBy(asc(conditions.name));
  const experimentRows = await db
    .select()
    .from(experiments)
    .where(eq(experiments.studyId, studyId))
    .orderBy(asc(experiments.name));
  const versions = experimentRows.length
    ? await db
        .select()
        .from(experimentVersions)
        .where(
          inArray(
            experimentVersions.experimentId,
            experimentRows.map((e) => e.id),
          ),
        )
        .orderBy(asc(experimentVersions.version))
    : [];
  const conditionName = (id: string | null) => conditionRows.find((c) => c.id === id)?.name ?? null;
  const files: Record<string, Uint8Array> = {
    "README.txt": strToU8(README),
    "study.json": strToU8(
      JSON.stringify(
        {
          study: {
            id: study!.id,
            title: study!.title,
            description: study!.description,
            status: study!.status,
            settings: study!.settings,
          },
          conditions: conditionRows.map((c) => ({
            name: c.name,
            description: c.description,
            experiment: experimentRows.find((e) => e.id === c.experimentId)?.name,
          })),
          participants: kept.map((p) => ({
            code: p.code,
            consent: { status: p.consentStatus, date: p.consentDate, documentVersion: p.consentVersion },
            demographics: p.demographics,
            condition: conditionName(p.conditionId),
            conditionOrder: Array.isArray(p.conditionOrder) ? (p.conditionOrder as string[]).map(conditionName) : null,
            assignment: p.assignment,
          })),
          withdrawnParticipants: people.length - kept.length,
          experiments: experimentRows.map((e) => ({
            name: e.name,
            robot: e.robotId,
            versions: versions
              .filter((v) => v.experimentId === e.id)
              .map((v) => ({
                version: v.version,
                hash: v.hash,
                pluginVersion: v.pluginVersion,
                publishedAt: v.publishedAt,
                protocol: v.snapshot,
              })),
          })),
          sessions: await db
            .select({
              plannedAt: sessions.plannedAt,
              participant: participants.code,
              condition: conditions.name,
              trialId: sessions.trialId,
            })
            .from(sessions)
            .innerJoin(participants, eq(participants.id, sessions.participantId))
            .innerJoin(conditions, eq(conditions.id, sessions.conditionId))
            .where(and(eq(sessions.studyId, studyId), ne(participants.consentStatus, "withdrawn")))
            .orderBy(asc(sessions.plannedAt)),
        },
        null,
        2,
      ),
    ),
    "methods.md": strToU8((await studyMethodsText(db, studyId)).markdown),
    "questionnaire-answers.csv": strToU8(answersCsv(await submitted(db, eq(questionnaireLinks.studyId, studyId)))),
    "codebook.csv": strToU8(codebookCsv()),
  };
  for (const version of versions) {
    const methods = await methodsText(db, version, studyId);
    // Two experiments of a study may share a name; their files may not.
    const name = `experiments/${methods.filename}`;
    files[name in files ? name.replace(/-methods\.md$/, `-${version.id.slice(0, 8)}-methods.md`) : name] = strToU8(
      methods.markdown,
    );
  }
  return { study: study!, files };
}

export async function studyArchive(db: Database, studyId: string) {
  const trialRows = await analysedTrials(db, studyId);
  const { study, files } = await studyFiles(db, studyId);
  // What a trial weighs in memory: its events and its robot state samples, counted in one query each.
  const ids = trialRows.map((t) => t.id);
  const [eventCounts, sampleCounts] = ids.length
    ? await Promise.all([
        db
          .select({ id: trialEvents.trialId, rows: count() })
          .from(trialEvents)
          .where(inArray(trialEvents.trialId, ids))
          .groupBy(trialEvents.trialId),
        db
          .select({ id: trialSamples.trialId, rows: count() })
          .from(trialSamples)
          .where(inArray(trialSamples.trialId, ids))
          .groupBy(trialSamples.trialId),
      ])
    : [[], []];
  const sizes = new Map<string, number>();
  for (const c of [...eventCounts, ...sampleCounts]) sizes.set(c.id, (sizes.get(c.id) ?? 0) + c.rows);
  const batches = batchesOf(trialRows.map((t) => ({ id: t.id, rows: sizes.get(t.id) ?? 0 })));
  // Codes are few (a key press each): every trial's in one file, read at once.
  files["codes.csv"] = strToU8(tableCsv(codesTable(await codeRowsOf(db, ids))));

  let out: ReadableStreamDefaultController<Uint8Array>;
  const zip = new Zip((error, chunk, final) => {
    if (error) return out.error(error);
    out.enqueue(chunk);
    if (final) out.close();
  });
  const add = (name: string, body: string | Uint8Array) => {
    const entry = new ZipDeflate(name, { level: 6 });
    zip.add(entry);
    entry.push(typeof body === "string" ? strToU8(body) : body, true);
  };
  let next = 0;
  const body = new ReadableStream<Uint8Array>({
    start(controller) {
      out = controller;
      for (const [name, content] of Object.entries(files)) add(name, content);
    },
    // Called only when the reader wants more: the next batch is read then, not before.
    async pull(controller) {
      const batch = batches[next++];
      if (!batch) return zip.end();
      try {
        for (const { files: trialFiles } of await trialsFiles(db, batch, ["json", "csv", "eaf", "samples"]))
          for (const file of trialFiles) add(`trials/${file.filename.replace(/^trial-/, "")}`, file.body);
      } catch (error) {
        // The headers have gone: the zip ends unfinished, which the researcher's download reports; the why is logged.
        logUnexpected(error, `the zip of study ${studyId}`);
        controller.error(new Error("The study's zip could not be finished"));
      }
    },
  });
  return {
    filename: `${fileSlug(study.title, "study")}.zip`,
    contentType: "application/zip",
    /** How many trials the zip holds: the researcher's progress counts against it. */
    trials: trialRows.length,
    body,
  };
}
