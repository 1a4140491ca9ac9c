// A trial's events CSV and its record as JSON are streamed as their rows are
// read (events, robot state samples, annotations, answers, codes), a page at a
// time: the same bytes as the whole file the study archive holds, and a
// download that fails part-way fails, rather than ending as a shorter file
// that looks complete.
import { afterAll, expect, it } from "vitest";
import { unscriptedLog } from "../../bench/support";
import { eq } from "drizzle-orm";
import {
  annotations,
  codeEvents,
  questionnaireLinks,
  questionnaireResponses,
  questionnaireVersions,
  trialSamples,
} from "../../src/store/schema";
import { ROWS_PER_READ, trialsFiles } from "../../src/server/trials/files";
import { ORIGIN, routeServer } from "../support/routes";

/** What a download fails with, read to its end; undefined if it ends without failing. */
async function failureOf(reader: ReadableStreamDefaultReader<Uint8Array>): Promise<unknown> {
  try {
    for (let read = await reader.read(); !read.done; read = await reader.read());
  } catch (error) {
    return error;
  }
  return undefined;
}
import { publishedVersion } from "./fixture";

const s = await routeServer();
afterAll(s.close);
const { db, f } = s;
const owner = f.api("owner");
const route = await import("../../src/app/api/trials/[trialId]/export/route");

/** Three pages of events and a part of a fourth. */
const EVENTS = 3 * ROWS_PER_READ + 1_001;

// Signed in once: the sign-in route refuses too many sign-ins in a row.
const signedIn = await s.signIn("owner");

/** The trial's download as the browser asks for it, signed in as the study's owner. */
async function download(trialId: string, format: "csv" | "json") {
  const res = await route.GET(
    new Request(`${ORIGIN}/api/trials/${trialId}/export?format=${format}`, { headers: signedIn }),
    { params: Promise.resolve({ trialId }) },
  );
  expect(res.status).toBe(200);
  return res;
}

/**
 * A completed trial of `count` events: unscripted lines (requested, dispatched,
 * completed), with notes among them whose text a CSV must quote and a
 * spreadsheet could run, a step's events, robot state samples and an annotation.
 */
async function seededTrial(count: number) {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  const t0 = new Date(Date.now() - 3_600_000);
  const stepId = (version.snapshot as { steps: { id: string }[] }).steps[0]!.id;
  const rows = unscriptedLog(trial.id, count, t0, (i) => i * 100).map((row, i) => {
    const other =
      i % 500 === 250
        ? { type: "note.added", text: `=HYPERLINK("x"), line ${i}\nsecond line, "quoted" ✓` }
        : i % 500 === 400
          ? { type: "step.entered", stepId }
          : undefined;
    if (!other) return row;
    return { ...row, type: other.type, action_id: null, payload: JSON.stringify(other), deviation: false };
  });
  const sql = db.$client;
  for (let start = 0; start < rows.length; start += 2_500)
    await sql`insert into trial_events ${sql(rows.slice(start, start + 2_500), "trial_id", "seq", "type", "server_time", "rel_ms", "actor_id", "step_id", "action_id", "payload", "deviation")}`;
  await sql`update trials set status = 'completed', t0 = ${t0.toISOString()}::timestamptz where id = ${trial.id}`;
  await db.insert(trialSamples).values(
    Array.from({ length: 50 }, (_, i) => ({
      trialId: trial.id,
      topic: "/joint_states",
      relMs: i * 20,
      data: { position: [i / 10] },
    })),
  );
  await owner.trials.annotate({ trialId: trial.id, relMs: 61_500, label: "Looks away", note: "during line 3" });
  return trial;
}

it("streams the events CSV and the record as JSON with the very bytes of the whole files", async () => {
  const trial = await seededTrial(EVENTS);
  const [whole] = await trialsFiles(db, [trial.id], ["csv", "json"]);
  const [csv, json] = whole!.files;

  const csvRes = await download(trial.id, "csv");
  expect(csvRes.headers.get("content-type")).toBe("text/csv; charset=utf-8");
  expect(csvRes.headers.get("content-disposition")).toBe(`attachment; filename="${csv!.filename}"`);
  // Streamed: no length is known before the end.
  expect(csvRes.headers.get("content-length")).toBeNull();
  const csvText = await csvRes.text();
  expect(csvText).toBe(csv!.body);
  expect(csvText.split("\r\n")).toHaveLength(EVENTS + 2);

  const jsonRes = await download(trial.id, "json");
  expect(jsonRes.headers.get("content-disposition")).toBe(`attachment; filename="${json!.filename}"`);
  const jsonText = await jsonRes.text();
  expect(jsonText).toBe(json!.body);
  const record = JSON.parse(jsonText);
  expect(record.events).toHaveLength(EVENTS);
  // The first line completed on the second page is named by its request, read on the first.
  const completed = record.events.slice(ROWS_PER_READ).find((e: { type: string }) => e.type === "action.completed");
  const request = record.events.find(
    (e: { type: string; actionId?: string }) => e.type === "action.requested" && e.actionId === completed.actionId,
  );
  expect(request.seq).toBeLessThanOrEqual(ROWS_PER_READ);
  expect(completed.actionName).toMatch(new RegExp(`Line ${request.seq - 1}$`));
  expect(record.samples).toHaveLength(50);
  expect(record.annotations).toMatchObject([{ label: "Looks away" }]);
});

it("streams a trial without events as the whole files are", async () => {
  const trial = await owner.trials.create({
    versionId: (await publishedVersion(owner, (await f.newStudy()).id)).version.id,
  });
  const [whole] = await trialsFiles(db, [trial.id], ["csv", "json"]);
  expect(await (await download(trial.id, "csv")).text()).toBe(whole!.files[0]!.body);
  expect(await (await download(trial.id, "json")).text()).toBe(whole!.files[1]!.body);
});

it("holds the log and the samples as they stood when the download began, while a live trial goes on", async () => {
  const trial = await seededTrial(EVENTS);
  const sql = db.$client;
  for (const [i, format] of (["csv", "json"] as const).entries()) {
    const [whole] = await trialsFiles(db, [trial.id], [format]);
    const res = await download(trial.id, format);
    const reader = res.body!.getReader();
    const first = await reader.read();
    // A line the wizard adds after the download began: a new unscripted action, and its request.
    const seq = EVENTS + 1 + i;
    const payload = { type: "action.requested", actionId: `late${i}`, actionType: "say", parameters: { text: "Late" } };
    await sql`insert into trial_events (trial_id, seq, type, server_time, payload) values (${trial.id}, ${seq}, 'action.requested', now(), ${JSON.stringify(payload)}::jsonb)`;
    // And the robot's state meanwhile, at the start of the trial's time (where a page of samples could take it in).
    await db.insert(trialSamples).values({ trialId: trial.id, topic: "/joint_states", relMs: 0, data: { late: i } });
    const chunks = [first.value!];
    for (let read = await reader.read(); !read.done; read = await reader.read()) chunks.push(read.value);
    expect(Buffer.concat(chunks).toString("utf8")).toBe(whole!.files[0]!.body);
  }
});

it("fails the download when the events cannot be read part-way: the file never looks complete", async () => {
  const trial = await seededTrial(EVENTS);
  const sql = db.$client;
  // After the header only, and after a page of events.
  for (const [format, pieces] of [
    ["csv", 1],
    ["json", 1],
    ["csv", 2],
    ["json", 2],
  ] as const) {
    const reader = (await download(trial.id, format)).body!.getReader();
    for (let i = 0; i < pieces; i++) expect((await reader.read()).done).toBe(false);
    // The log goes away after the first bytes have left (the headers with them).
    await sql`alter table trial_events rename to trial_events_away`;
    try {
      const failed = await failureOf(reader);
      expect(failed).toBeInstanceOf(Error);
      expect((failed as Error).message).toMatch(/^The (events CSV|record) of trial .+ could not be finished$/);
      expect((failed as Error).message).not.toMatch(/relation|trial_events_away|select/i);
    } finally {
      await sql`alter table trial_events_away rename to trial_events`;
    }
  }
});

/** Enough rows of a kind for three pages, with ties of the order's first key across their boundaries. */
const ROWS = 2 * ROWS_PER_READ + 123;

/**
 * A trial of a few events whose robot state samples, annotations, submitted
 * answers and codes each fill more than a page: written out of order, with
 * ties (the same time, the same participant and questionnaire) that only the
 * rows' ids order, a page boundary among them. And a withdrawn participant's
 * answers, which no file holds.
 */
async function trialOfManyRows() {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const participant = await owner.participants.create({
    studyId: study.id,
    code: "P01",
    consentStatus: "given",
    consentDate: new Date(),
  });
  const withdrawn = await owner.participants.create({ studyId: study.id, code: "P00", consentStatus: "withdrawn" });
  const trial = await owner.trials.create({ versionId: version.id, participantId: participant.id });
  const sql = db.$client;
  const t0 = new Date(Date.now() - 3_600_000);
  const log = unscriptedLog(trial.id, 30, t0, (i) => i * 100);
  await sql`insert into trial_events ${sql(log, "trial_id", "seq", "type", "server_time", "rel_ms", "actor_id", "step_id", "action_id", "payload", "deviation")}`;
  await sql`update trials set status = 'completed', t0 = ${t0.toISOString()}::timestamptz where id = ${trial.id}`;
  // Backwards in time, seven to a millisecond: the order is the time's, then the order they were written in.
  const backwards = Array.from({ length: ROWS }, (_, i) => ROWS - 1 - i);
  for (let start = 0; start < ROWS; start += 2_500)
    await db.insert(trialSamples).values(
      backwards.slice(start, start + 2_500).map((i) => ({
        trialId: trial.id,
        topic: i % 2 ? "/joint_states" : "/battery_state",
        relMs: Math.floor(i / 7) + 0.5,
        data: { position: [i / 10, -i], name: `joint "${i}"\n` },
      })),
    );
  for (let start = 0; start < ROWS; start += 2_500)
    await db.insert(annotations).values(
      backwards.slice(start, start + 2_500).map((i) => ({
        trialId: trial.id,
        authorId: i % 3 ? f.people.owner.id : null,
        relMs: Math.floor(i / 3) * 10,
        label: `Looks "away" ${i}`,
        note: i % 5 ? "" : "during, the\nline",
      })),
    );
  const { id: schemeId } = await owner.coding.createScheme({ studyId: study.id, template: "participant-engagement" });
  const { id: versionId } = await owner.coding.publishScheme({ codingSchemeId: schemeId });
  for (let start = 0; start < ROWS; start += 2_500)
    await db.insert(codeEvents).values(
      backwards.slice(start, start + 2_500).map((i) => ({
        trialId: trial.id,
        observerId: i % 4 ? f.people.observer.id : null,
        versionId,
        setId: i % 2 ? "gaze" : "expression",
        codeId: i % 2 ? "robot" : "smile",
        kind: i % 2 ? ("state" as const) : ("point" as const),
        startMs: Math.floor(i / 11) * 100,
        endMs: i % 2 ? Math.floor(i / 11) * 100 + 50 : null,
        modifiers: i % 3 ? [] : ["laugh", "loud"],
      })),
    );
  const sus = await owner.questionnaires.create({ studyId: study.id, instrument: "sus" });
  await owner.questionnaires.publish({ questionnaireId: sus.id });
  const [shown] = await db
    .select({ id: questionnaireVersions.id })
    .from(questionnaireVersions)
    .where(eq(questionnaireVersions.questionnaireId, sus.id));
  // One questionnaire, one participant: a page of answers ends among ties ordered by their ids alone.
  const answered = ROWS_PER_READ + 7;
  for (let start = 0; start < answered; start += 2_500) {
    const links = Array.from({ length: Math.min(2_500, answered - start) }, (_, k) => ({
      tokenHash: crypto.randomUUID(),
      studyId: study.id,
      versionId: shown!.id,
      participantId: start + k === 3 ? withdrawn.id : participant.id,
      trialId: trial.id,
      expiresAt: new Date(Date.now() + 3_600_000),
    }));
    const made = await db.insert(questionnaireLinks).values(links).returning({ id: questionnaireLinks.id });
    await db.insert(questionnaireResponses).values(
      made.map((link, k) => ({
        linkId: link.id,
        answers: { q1: (start + k) % 5, q2: [1, "two"] },
        status: "submitted" as const,
        score: { total: start + k },
        submittedAt: new Date(t0.getTime() + start + k),
      })),
    );
  }
  return { trial, answered };
}

it("streams a record of many samples, annotations, answers and codes with the very bytes of the whole record", async () => {
  const { trial, answered } = await trialOfManyRows();
  const [whole] = await trialsFiles(db, [trial.id], ["json"]);
  const text = await (await download(trial.id, "json")).text();
  expect(text).toBe(whole!.files[0]!.body);
  const record = JSON.parse(text);
  expect(record.samples).toHaveLength(ROWS);
  expect(record.annotations).toHaveLength(ROWS);
  expect(record.codes).toHaveLength(ROWS);
  // The withdrawn participant's answers are left out.
  expect(record.questionnaires).toHaveLength(answered - 1);
  expect(record.samples.slice(0, 8).map((s: { relMs: number }) => s.relMs)).toEqual([
    0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 1.5,
  ]);
  // Written backwards: ties are in the order they were written.
  expect(record.samples.slice(0, 2).map((s: { data: { position: number[] } }) => s.data.position[1])).toEqual([-6, -5]);
  // Annotations at one time in the order of their ids (random): the three at 0 ms, each with its author's name.
  expect(
    record.annotations
      .slice(0, 3)
      .map((a: { relMs: number; label: string; authorName: string | null }) => [a.relMs, a.label, a.authorName])
      .sort(),
  ).toEqual([
    [0, 'Looks "away" 0', null],
    [0, 'Looks "away" 1', f.people.owner.name],
    [0, 'Looks "away" 2', f.people.owner.name],
  ]);
  // Codes in time order (ties in the order of their ids, random): the eleven at 0 ms first.
  expect(record.codes.slice(0, 12).map((c: { start_ms: number }) => c.start_ms)).toEqual([...Array(11).fill(0), 100]);
  expect(record.questionnaires[0]).toMatchObject({ questionnaire: expect.any(String), participantCode: "P01" });
  expect(Object.keys(record)).toEqual([
    "schemaVersion",
    "trial",
    "protocol",
    "events",
    "annotations",
    "questionnaires",
    "recordings",
    "samples",
    "codes",
  ]);
});

it("fails the record's download when its samples, annotations, answers or codes cannot be read part-way", async () => {
  const { trial } = await trialOfManyRows();
  const sql = db.$client;
  for (const table of ["annotations", "questionnaire_responses", "trial_samples", "code_events"]) {
    const reader = (await download(trial.id, "json")).body!.getReader();
    // The first piece: the record's head, before any list is read.
    expect((await reader.read()).done).toBe(false);
    await sql`alter table ${sql(table)} rename to gone_away`;
    try {
      const failed = await failureOf(reader);
      expect(failed, table).toBeInstanceOf(Error);
      expect((failed as Error).message).toMatch(/^The record of trial .+ could not be finished$/);
    } finally {
      await sql`alter table gone_away rename to ${sql(table)}`;
    }
  }
});
