// A trial's events CSV and its record as JSON are streamed as their events are
// read, a page at a time: the same bytes as the whole file the study archive
// holds, and a download that fails part-way fails, rather than ending as a
// shorter file that looks complete.
import { afterAll, expect, it } from "vitest";
import { unscriptedLog } from "../../bench/support";
import { trialSamples } from "../../src/store/schema";
import { EVENTS_PER_READ, trialsFiles } from "../../src/server/trials/files";
import { ORIGIN, routeServer } from "../support/routes";
import { publishedVersion } from "./fixture";

const s = await routeServer();
afterAll(s.close);
const { db, f } = s;
const owner = f.api("owner");
const route = await import("../../src/app/api/trials/[trialId]/export/route");

/** Three pages of events and a part of a fourth. */
const EVENTS = 3 * EVENTS_PER_READ + 1_001;

/** The trial's download as the browser asks for it, signed in as the study's owner. */
async function download(trialId: string, format: "csv" | "json") {
  const res = await route.GET(
    new Request(`${ORIGIN}/api/trials/${trialId}/export?format=${format}`, { headers: await s.signIn("owner") }),
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
  const completed = record.events.slice(EVENTS_PER_READ).find((e: { type: string }) => e.type === "action.completed");
  const request = record.events.find(
    (e: { type: string; actionId?: string }) => e.type === "action.requested" && e.actionId === completed.actionId,
  );
  expect(request.seq).toBeLessThanOrEqual(EVENTS_PER_READ);
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

it("holds the log as it stood when the download began, while a live trial goes on", async () => {
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
    const chunks = [first.value!];
    for (let read = await reader.read(); !read.done; read = await reader.read()) chunks.push(read.value);
    expect(Buffer.concat(chunks).toString("utf8")).toBe(whole!.files[0]!.body);
  }
});

it("fails the download when the events cannot be read part-way: the file never looks complete", async () => {
  const trial = await seededTrial(EVENTS);
  const sql = db.$client;
  // After the header only (while the requests are read for the names), and after a page of events.
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
      let failed: unknown;
      try {
        for (let read = await reader.read(); !read.done; read = await reader.read());
      } catch (error) {
        failed = error;
      }
      expect(failed).toBeInstanceOf(Error);
      expect((failed as Error).message).toMatch(/^The (events CSV|record) of trial .+ could not be finished$/);
      expect((failed as Error).message).not.toMatch(/relation|trial_events_away|select/i);
    } finally {
      await sql`alter table trial_events_away rename to trial_events`;
    }
  }
});
