// bench/analysis: the analysis of a 60-minute trial with 2,000 events (or as
// many as the first argument says: `bun bench/analysis.ts 100000`) and 180,000
// robot samples (joint states at 50 Hz). Measures the data (the trial, its
// events and its samples thinned for the chart, over HTTP as the page loads
// them) and, in Chromium, the page until it is interactive (figures, table
// and chart drawn). Targets: data under 500 ms, page under 2 s (issue 15 asks
// the page under 2 s at 100k events too).
// Takes a few minutes (and the app's build first, once).
import { launchBrowser, newContext, signInAs } from "../tests/support/browser";
import { DEMO_PASSWORD, startApp } from "../tests/support/app";
import { apiClient, signIn } from "../tests/support/http";
import { loadavg } from "node:os";
import { createDatabase } from "../src/store/client";
import { insertLog, report, scratchDatabase, unscriptedLog } from "./support";

const EVENTS = Number(process.argv[2] ?? 2000);
if (!Number.isInteger(EVENTS) || EVENTS < 2) throw new Error("bench/analysis takes the number of events, at least 2");
const SAMPLES = 180_000;
const MINUTES = 60;
/** Each figure's count: a p99 is quoted, so at least 100. */
const RUNS = 100;

const database = await scratchDatabase();
const app = await startApp({ env: { DATABASE_URL: database.url, HRI_SEED_DEMO: "true" } });
const { db, close } = createDatabase(database.url, { max: 2 });
try {
  const cookie = await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD);
  const api = apiClient(app.url, cookie);
  // The log as the page loads it: its own route, parsed as the browser parses it.
  const log = async () => {
    const res = await fetch(`${app.url}/api/trials/${trial.id}/events`, { headers: { cookie } });
    if (!res.ok) throw new Error(`The trial's log: ${res.status} ${await res.text()}`);
    return res.json();
  };
  const [study] = await api.studies.mine.query();
  const [experiment] = await api.experiments.list.query({ studyId: study!.id });
  const version = await api.versions.publish.mutate({ experimentId: experiment!.id });
  const [participant] = await api.participants.list.query({ studyId: study!.id });
  const trial = await api.trials.create.mutate({ versionId: version.id, participantId: participant!.id });

  // A long session: mostly unscripted robot actions, each requested, dispatched and completed.
  const t0 = new Date(Date.now() - MINUTES * 60_000);
  const span = MINUTES * 60_000;
  const events = unscriptedLog(trial.id, EVENTS, t0, (i) => Math.round((i / EVENTS) * span));
  const sql = db.$client;
  await insertLog(db, events);
  const names = ["HeadYaw", "HeadPitch", "LShoulderPitch", "RShoulderPitch"];
  for (let start = 0; start < SAMPLES; start += 10_000) {
    const rows = Array.from({ length: Math.min(10_000, SAMPLES - start) }, (_, k) => {
      const relMs = Math.round(((start + k) / SAMPLES) * span);
      return {
        trial_id: trial.id,
        topic: "/joint_states",
        rel_ms: relMs,
        data: JSON.stringify({ name: names, position: names.map((_, j) => Math.sin(relMs / 1000 + j)) }),
      };
    });
    await sql`insert into trial_samples ${sql(rows, "trial_id", "topic", "rel_ms", "data")}`;
  }
  await sql`update trials set status = 'completed', t0 = ${t0.toISOString()}::timestamptz, ended_at = now() where id = ${trial.id}`;
  // As autovacuum would after so many inserts, long before a researcher opens an hour's trial (bench/open-large
  // does the same): without statistics the first loads took twice the others (the first two of 100 timed).
  await sql`analyze trial_events, trial_samples`;

  // What the analysis page loads first, all at once.
  const pageData = () =>
    Promise.all([
      api.trials.get.query({ trialId: trial.id }),
      log(),
      api.trials.samples.query({ trialId: trial.id, topic: "/joint_states", maxPoints: 2000 }),
    ]);
  // Once untimed: a route's first request after the server starts loads its code (half a second, once per start),
  // as the set-up's calls above did for the API's; the figures are those of a server that has served it before.
  await pageData();
  const data: number[] = [];
  for (let i = 0; i < RUNS; i++) {
    const started = performance.now();
    await pageData();
    data.push(performance.now() - started);
  }

  // The machine is shared: its load says how far to trust the figures.
  const load = () =>
    loadavg()
      .map((n) => n.toFixed(2))
      .join(" ");
  console.log(`A ${MINUTES}-minute trial with ${EVENTS} events and ${SAMPLES} robot samples (load average ${load()}):`);
  report("trial, events and samples loaded over HTTP", data, 500);

  const browser = await launchBrowser();
  const page = await (await newContext(browser, app.url)).newPage();
  await signInAs(page, "researcher@demo.hristudio", DEMO_PASSWORD);
  const interactive: number[] = [];
  for (let i = 0; i < RUNS; i++) {
    const started = performance.now();
    await page.goto(`/trials/${trial.id}/analysis`);
    await page.getByRole("heading", { name: "Robot joint angles" }).waitFor({ timeout: 60_000 });
    // Interactive: the events list answers the keyboard, End reaching the last event (the list draws only what is in view).
    const list = page.getByRole("group", { name: /^Events and annotations/ });
    await list.getByRole("button", { name: /trial\.started/ }).focus({ timeout: 60_000 });
    await page.keyboard.press("End");
    await list.getByRole("button", { name: /trial\.completed/ }).waitFor({ timeout: 60_000 });
    interactive.push(performance.now() - started);
  }
  await browser.close();
  report("analysis page in Chromium until interactive", interactive, 2000);
  console.log(`load average at the end: ${load()}`);
} finally {
  await close();
  await app.stop();
  await database.stop();
}
