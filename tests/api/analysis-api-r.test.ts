// The analysis API from R, beside the pandas example: Debian's R with readr
// and httr2 reads a study's tables over HTTP with a token, and gets the text
// as it was typed (no spreadsheet formula guard: a label "-5 looks away"
// stays that) and the columns' types (numbers as numbers, times as times).
import { execFile } from "node:child_process";
import { promisify } from "node:util";
import { createServer } from "node:http";
import type { AddressInfo } from "node:net";
import { join } from "node:path";
import { afterAll, expect, it } from "vitest";
import { API_BASE } from "../../src/core/analysis/api";
import { appendEvents } from "../../src/store/event-store";
import { annotations } from "../../src/store/schema";
import { publishedVersion } from "./fixture";
import { analysisRoute, routeServer } from "../support/routes";

const SCRIPT = join(import.meta.dirname, "..", "r", "read_table.R");
// Labels a coder types that a spreadsheet would take for formulas.
const LABELS = ["-5 looks away", "=gaze(robot)", "+1 nods", "@participant smiles"];

const s = await routeServer();
const owner = await s.apiAs(await s.signIn("owner"));
const study = await s.f.newStudy("Gaze study");
const { version } = await publishedVersion(owner, study.id);
const participant = await owner.participants.create({
  studyId: study.id,
  code: "P01",
  consentStatus: "given",
  consentDate: new Date(),
});
const trial = await owner.trials.create({ versionId: version.id, participantId: participant.id });
await appendEvents(s.db, { id: trial.id, lastSeq: 0, t0: null }, [{ type: "trial.started" }], s.f.people.owner.id);
await s.db
  .insert(annotations)
  .values(
    LABELS.map((label, i) => ({ trialId: trial.id, relMs: 1000 * (i + 1), label, authorId: s.f.people.observer.id })),
  );
const token = (await owner.tokens.create({ name: "R", studyIds: [study.id], expiresInDays: 30 })).secret;

// The API over a real socket, as R reaches a server.
const http = createServer(async (req, res) => {
  const headers = Object.fromEntries(Object.entries(req.headers).map(([k, v]) => [k, String(v)]));
  const answer = await analysisRoute(new Request(`http://127.0.0.1${req.url}`, { headers }));
  res.writeHead(answer.status, Object.fromEntries(answer.headers));
  res.end(Buffer.from(await answer.arrayBuffer()));
});
await new Promise<void>((ok) => http.listen(0, "127.0.0.1", ok));
const base = `http://127.0.0.1:${(http.address() as AddressInfo).port}${API_BASE}`;
afterAll(async () => {
  http.close();
  await s.close();
});

/** The table's columns with R's class of each, and the values of one column, as the R script prints them. */
async function readInR(path: string, column: string) {
  // Not spawnSync: the server R asks is in this process, and must go on answering.
  const run = await promisify(execFile)("Rscript", [SCRIPT, `${base}${path}`, column], {
    env: { ...process.env, HRI_TOKEN: token },
    timeout: 120_000,
  }).catch((error: Error & { stderr?: string }) => {
    throw new Error(
      `Rscript failed (it needs Debian's r-base-core, r-cran-readr and r-cran-httr2): ${error.stderr || error.message}`,
    );
  });
  const [classes, values] = run.stdout.split("--\n");
  return {
    classes: Object.fromEntries(
      classes!
        .trim()
        .split("\n")
        .map((line) => line.split("\t")),
    ),
    values: values!.replace(/\n$/, "").split("\n"),
  };
}

it("reads the annotations' labels as they were typed, and their times as numbers", async () => {
  const { classes, values } = await readInR(`/studies/${study.id}/annotations`, "label");
  expect(values).toEqual(LABELS);
  expect(classes).toMatchObject({ trial_id: "character", rel_ms: "numeric", label: "character" });
});

it("reads the trials with their start as a time and their events as numbers", async () => {
  const trials = await readInR(`/studies/${study.id}/trials`, "trial_id");
  expect(trials.values).toEqual([trial.id]);
  expect(trials.classes).toMatchObject({ started_at: "POSIXct", version: "numeric" });
  const events = await readInR(`/studies/${study.id}/events`, "type");
  expect(events.values).toEqual(["trial.started"]);
  expect(events.classes).toMatchObject({ seq: "numeric", server_time: "POSIXct", payload: "character" });
});
