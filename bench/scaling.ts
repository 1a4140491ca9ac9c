// bench/scaling: how each path's cost grows with a study. A study of 10,
// 100 and 1,000 trials (200 events each) and a trial of 1k, 10k and 100k
// events (unscripted lines: requested, dispatched, completed), seeded straight
// in a scratch database; each path is called as the web server calls it (the
// tRPC procedure, in process) and timed, with the process's peak memory above
// its level before the call. The growth ratio is the time's growth over the
// size's (1.0 is linear). Targets (issue 15): at 1,000 trials the Trials tab,
// Results tab and first byte of the zip under 1 s; at 100k events opening the
// trial under 1 s and the exports under 2 s, their first byte under 1 s. The
// analysis page in Chromium is bench/analysis (it needs the built app).
// `bun bench/scaling.ts trials` measures the trials of 1k to 100k events and the
// trials of 1.8k to 180k robot state samples only; `… samples` the latter only;
// `… studies` the studies of 10 to 1,000 trials only, `… results` their
// Trials and Results tabs only (a minute), and `… methods` the study's
// methods text only (at 1,000 trials, 200k events; a minute or two). The
// samples part has the MCAP export too, its schemas read off every message.
// Takes several minutes; a part alone, a minute or two.
import { eventsSince } from "../src/store/event-store";
import { createDatabase } from "../src/store/client";
import { fold } from "../src/core/trial/fold";
import type { TrialEvent, TrialProtocol } from "../src/core/trial";
import { trialsFiles } from "../src/server/trials/files";
import { trialSamples } from "../src/store/schema";
import { buildFixture, publishedVersion } from "../tests/api/fixture";
import { insertLog, percentile, scratchDatabase, unscriptedLog } from "./support";

const RUNS = 3;
const STUDY_SIZES = [10, 100, 1000];
const EVENTS_PER_TRIAL = 200;
const TRIAL_SIZES = [1000, 10_000, 100_000];
/** Robot state samples of a trial (1k events each): a 30-minute trial at 100 Hz logs 180,000. */
const SAMPLE_SIZES = [1800, 18_000, 180_000];
const TRIALS_ONLY = process.argv[2] === "trials" || process.argv[2] === "samples";
const SAMPLES_ONLY = process.argv[2] === "samples";
const TABS_ONLY = process.argv[2] === "results";
const METHODS_ONLY = process.argv[2] === "methods";
const STUDIES_ONLY = process.argv[2] === "studies" || TABS_ONLY || METHODS_ONLY;

const database = await scratchDatabase();
const { db, close } = createDatabase(database.url, { max: 4 });
const sql = db.$client;

/** A trial's log of unscripted lines, as bench/analysis seeds it, an event every 100 ms. */
const eventRows = (trialId: string, count: number, t0: Date) => unscriptedLog(trialId, count, t0, (i) => i * 100);

/** `count` completed trials of a new study, each with its consenting participant and `events` events. */
async function seedStudy(f: Awaited<ReturnType<typeof buildFixture>>, count: number, events: number) {
  const owner = f.api("owner");
  const study = await f.newStudy(`Scaling ${count}×${events}`);
  const { experiment, version } = await publishedVersion(owner, study.id);
  // Every participant in the one condition, as a study's are: the methods text and results count per condition.
  const condition = await owner.conditions.create({ studyId: study.id, name: "Gestures", experimentId: experiment.id });
  const t0 = new Date(Date.now() - 3_600_000);
  const trialIds: string[] = [];
  for (let start = 0; start < count; start += 500) {
    const n = Math.min(500, count - start);
    const people = Array.from({ length: n }, (_, k) => ({
      id: crypto.randomUUID(),
      study_id: study.id,
      code: `P${String(start + k + 1).padStart(4, "0")}`,
      consent_status: "given",
      condition_id: condition.id,
    }));
    await sql`insert into participants ${sql(people)}`;
    const rows = people.map((p, k) => ({
      id: crypto.randomUUID(),
      study_id: study.id,
      experiment_id: experiment.id,
      version_id: version.id,
      participant_id: p.id,
      wizard_id: f.people.wizard.id,
      created_by: f.people.owner.id,
      status: "completed",
      t0: t0.toISOString(),
      ended_at: new Date(t0.getTime() + events * 100).toISOString(),
      created_at: new Date(t0.getTime() + start + k).toISOString(),
    }));
    await sql`insert into trials ${sql(rows)}`;
    trialIds.push(...rows.map((r) => r.id));
  }
  for (const id of trialIds) await insertLog(db, eventRows(id, events, t0));
  return { study, version, trialIds };
}

/** `count` joint-state samples of the trial, one every 10 ms, as a robot's state subscription logs them. */
async function insertSamples(trialId: string, count: number) {
  const joints = ["HeadYaw", "HeadPitch", "LShoulderPitch", "LShoulderRoll", "RShoulderPitch", "RShoulderRoll"];
  for (let start = 0; start < count; start += 5000) {
    const rows = Array.from({ length: Math.min(5000, count - start) }, (_, k) => {
      const i = start + k;
      return {
        trialId,
        topic: "/joint_states",
        relMs: i * 10,
        data: { name: joints, position: joints.map((_, j) => Math.sin(i / 100 + j)), effort: [] },
      };
    });
    await db.insert(trialSamples).values(rows);
  }
}

/**
 * Runs `path` RUNS times (each after `setup`, untimed): the median time, the slowest (too few runs for a p99),
 * and the largest peak of memory above where it started.
 */
async function measure(path: () => Promise<unknown>, setup?: () => Promise<unknown>) {
  const times: number[] = [];
  let peakMb = 0;
  for (let i = 0; i < RUNS; i++) {
    await setup?.();
    Bun.gc(true);
    const before = process.memoryUsage().rss;
    let peak = before;
    const sampler = setInterval(() => {
      peak = Math.max(peak, process.memoryUsage().rss);
    }, 5);
    const started = performance.now();
    await path();
    times.push(performance.now() - started);
    clearInterval(sampler);
    peak = Math.max(peak, process.memoryUsage().rss);
    peakMb = Math.max(peakMb, (peak - before) / 1e6);
  }
  const sorted = [...times].sort((a, b) => a - b);
  return { ms: percentile(sorted, 50), max: sorted.at(-1)!, peakMb };
}

function print(
  path: string,
  sizes: number[],
  unit: string,
  results: { ms: number; max: number; peakMb: number }[],
  targetMs?: number,
) {
  console.log(`\n${path}`);
  results.forEach((r, i) => {
    const growth =
      i === 0 ? "" : `  growth ${(r.ms / results[i - 1]!.ms / (sizes[i]! / sizes[i - 1]!)).toFixed(2)} of linear`;
    const target =
      targetMs === undefined || i < results.length - 1
        ? ""
        : `  target < ${targetMs} ms: ${r.ms < targetMs ? "met" : "NOT met"} (ratio ${(r.ms / targetMs).toFixed(2)})`;
    console.log(
      `  ${String(sizes[i]).padStart(7)} ${unit.padEnd(7)} n=${RUNS}  p50=${r.ms.toFixed(1).padStart(9)} ms  max=${r.max.toFixed(1).padStart(9)} ms  peak memory +${r.peakMb.toFixed(1).padStart(6)} MB${growth}${target}`,
    );
  });
}

try {
  const f = await buildFixture(db);
  const owner = f.api("owner");
  /** As the download routes call: the files come as streams. */
  const downloads = f.routeApi("owner");
  console.log(
    `Machine load (1, 5, 15 min): ${(await Bun.file("/proc/loadavg").text()).split(" ").slice(0, 3).join(" ")}`,
  );

  const studiesBySize: Awaited<ReturnType<typeof seedStudy>>[] = [];
  if (!TRIALS_ONLY) for (const size of STUDY_SIZES) studiesBySize.push(await seedStudy(f, size, EVENTS_PER_TRIAL));
  const trialsBySize: Awaited<ReturnType<typeof seedStudy>>[] = [];
  if (!SAMPLES_ONLY && !STUDIES_ONLY) for (const size of TRIAL_SIZES) trialsBySize.push(await seedStudy(f, 1, size));
  const sampledBySize: Awaited<ReturnType<typeof seedStudy>>[] = [];
  if (!STUDIES_ONLY)
    for (const size of SAMPLE_SIZES) {
      const seeded = await seedStudy(f, 1, 1000);
      await insertSamples(seeded.trialIds[0]!, size);
      sampledBySize.push(seeded);
    }
  await sql`analyze`;

  const byStudy = async (
    path: (studyId: string) => Promise<unknown>,
    setup?: (studyId: string) => Promise<unknown>,
  ) => {
    const results = [];
    for (const { study } of studiesBySize)
      results.push(await measure(() => path(study.id), setup && (() => setup(study.id))));
    return results;
  };
  const byTrial = async (
    path: (trialId: string, protocol: TrialProtocol) => Promise<unknown>,
    trials: typeof trialsBySize = trialsBySize,
  ) => {
    const results = [];
    for (const { trialIds, version } of trials)
      results.push(await measure(() => path(trialIds[0]!, version.snapshot as TrialProtocol)));
    return results;
  };
  const drain = async (body: ReadableStream<Uint8Array>) => {
    const reader = body.getReader();
    let bytes = 0;
    for (let read = await reader.read(); !read.done; read = await reader.read()) bytes += read.value.length;
    return bytes;
  };

  if (!TRIALS_ONLY) await studies();
  /** A download's body, which must be streamed: the bench measures the streamed path, not another. */
  const streamed = (body: unknown) => {
    if (!(body instanceof ReadableStream)) throw new Error("The trial's download was not streamed");
    return body as ReadableStream<Uint8Array>;
  };

  /**
   * A study path that reads its ended trials' figures: first with none kept (each ended trial's log is folded
   * once and its figures kept, on the first call after it ends), then with them kept (the 1 s target).
   */
  async function firstThenKept(path: (studyId: string) => Promise<unknown>, first: string, kept: string) {
    const dropFigures = (studyId: string) =>
      sql`delete from trial_figures using trials where trials.id = trial_id and trials.study_id = ${studyId}`;
    print(first, STUDY_SIZES, "trials", await byStudy(path, dropFigures));
    print(kept, STUDY_SIZES, "trials", await byStudy(path), 1000);
  }

  /** The study-sized paths: the Trials and Results tabs, the zip, the analysis API. */
  async function studies() {
    console.log(`Studies of ${STUDY_SIZES.join(", ")} trials (${EVENTS_PER_TRIAL} events each):`);
    if (METHODS_ONLY) return methods();
    print(
      "Trials tab (trials.list)",
      STUDY_SIZES,
      "trials",
      await byStudy((studyId) => owner.trials.list({ studyId })),
      1000,
    );
    const resultsTab = (studyId: string) =>
      Promise.all([owner.studies.figures({ studyId }), owner.studies.resultsByCondition({ studyId })]);
    await firstThenKept(
      resultsTab,
      "Results tab, first call after the trials ended (no figures kept yet: every log folded)",
      "Results tab (studies.figures and resultsByCondition)",
    );
    if (TABS_ONLY) return;
    await methods();
    print(
      "Study zip: first byte",
      STUDY_SIZES,
      "trials",
      await byStudy(async (studyId) => {
        const { body } = await downloads.studies.exportArchive({ studyId });
        const reader = body.getReader();
        await reader.read();
        await reader.cancel();
      }),
      1000,
    );
    const zipBytes: number[] = [];
    print(
      "Study zip: whole",
      STUDY_SIZES,
      "trials",
      await byStudy(async (studyId) => {
        zipBytes.push(await drain((await downloads.studies.exportArchive({ studyId })).body));
      }),
    );
    console.log(`  (zip sizes: ${[0, 1, 2].map((i) => `${(zipBytes[i * RUNS]! / 1e6).toFixed(1)} MB`).join(", ")})`);
    print(
      "Analysis API events table of the study (/api/v1)",
      STUDY_SIZES,
      "trials",
      await byStudy(async (studyId) => {
        const { studyEventsTable } = await import("../src/server/analysis/tables");
        return studyEventsTable(db, studyId);
      }),
    );
  }

  /** The study's methods text (its Methods tab and the zip's methods.md): every trial's figures, per condition. */
  async function methods() {
    const text = (studyId: string) => owner.studies.methods({ studyId });
    await firstThenKept(
      text,
      "Study methods text, first call after the trials ended (every log folded)",
      "Study methods text (studies.methods), the trials' figures kept",
    );
  }

  if (!SAMPLES_ONLY && !STUDIES_ONLY) await trials();
  if (!STUDIES_ONLY) await sampled();

  /** The trial-sized paths: opening the trial, the analysis page's data, the events CSV and the record. */
  async function trials() {
    console.log(`\nTrials of ${TRIAL_SIZES.join(", ")} events (unscripted lines):`);
    print(
      "Opening the trial (its events read and folded)",
      TRIAL_SIZES,
      "events",
      await byTrial(async (trialId, protocol) =>
        fold(protocol, (await eventsSince(db, trialId)) as unknown as TrialEvent[]),
      ),
      1000,
    );
    print(
      "Analysis page's data (trials.get and its log's route, trials.eventsJson)",
      TRIAL_SIZES,
      "events",
      await byTrial((trialId) =>
        Promise.all([
          owner.trials.get({ trialId }),
          downloads.trials.eventsJson({ trialId }).then(({ body }) => drain(streamed(body))),
        ]),
      ),
    );
    for (const [format, name] of [
      ["csv", "Events export (CSV)"],
      ["json", "Trial record export (JSON)"],
    ] as const) {
      print(
        `${name}: first byte`,
        TRIAL_SIZES,
        "events",
        await byTrial(async (trialId) => {
          const reader = streamed((await downloads.trials.export({ trialId, format })).body).getReader();
          await reader.read();
          await reader.cancel();
        }),
        1000,
      );
      const bytes: number[] = [];
      print(
        `${name}: whole, streamed`,
        TRIAL_SIZES,
        "events",
        await byTrial(async (trialId) => {
          bytes.push(await drain(streamed((await downloads.trials.export({ trialId, format })).body)));
        }),
        2000,
      );
      console.log(`  (sizes: ${[0, 1, 2].map((i) => `${(bytes[i * RUNS]! / 1e6).toFixed(1)} MB`).join(", ")})`);
      // The peak above counts garbage the collector has not yet reclaimed; with a full collection after
      // each piece it is what the download holds (its time is then the collector's, not the download's).
      print(
        `${name}: whole, streamed, collected after each piece (memory held)`,
        TRIAL_SIZES,
        "events",
        await byTrial(async (trialId) => {
          const reader = streamed((await downloads.trials.export({ trialId, format })).body).getReader();
          for (let read = await reader.read(); !read.done; read = await reader.read()) Bun.gc(true);
        }),
      );
      // The same bytes built whole in memory, as the study's zip takes a batch of trials: what the download did before.
      print(
        `${name}: built whole in memory (the zip's batch path)`,
        TRIAL_SIZES,
        "events",
        await byTrial((trialId) => trialsFiles(db, [trialId], [format])),
      );
    }
  }

  /** The record of a trial whose robot state samples outnumber its events: they are streamed as its events are. */
  async function sampled() {
    console.log(`\nTrials of 1,000 events and ${SAMPLE_SIZES.join(", ")} robot state samples:`);
    const bytes: number[] = [];
    const print3 = (name: string, results: { ms: number; max: number; peakMb: number }[], targetMs?: number) =>
      print(`Trial record export (JSON): ${name}`, SAMPLE_SIZES, "samples", results, targetMs);
    print3(
      "first byte",
      await byTrial(async (trialId) => {
        const reader = streamed((await downloads.trials.export({ trialId, format: "json" })).body).getReader();
        await reader.read();
        await reader.cancel();
      }, sampledBySize),
      1000,
    );
    print3(
      "whole, streamed",
      await byTrial(async (trialId) => {
        bytes.push(await drain(streamed((await downloads.trials.export({ trialId, format: "json" })).body)));
      }, sampledBySize),
    );
    console.log(`  (sizes: ${[0, 1, 2].map((i) => `${(bytes[i * RUNS]! / 1e6).toFixed(1)} MB`).join(", ")})`);
    print3(
      "whole, streamed, collected after each piece (memory held)",
      await byTrial(async (trialId) => {
        const reader = streamed((await downloads.trials.export({ trialId, format: "json" })).body).getReader();
        for (let read = await reader.read(); !read.done; read = await reader.read()) Bun.gc(true);
      }, sampledBySize),
    );
    print3(
      "built whole in memory (the zip's batch path)",
      await byTrial((trialId) => trialsFiles(db, [trialId], ["json"]), sampledBySize),
    );
    // The MCAP is built whole (its summary and index follow the messages), each topic's schema read off every message.
    const mcapBytes: number[] = [];
    print(
      "MCAP export (trials.export mcap), whole",
      SAMPLE_SIZES,
      "samples",
      await byTrial(async (trialId) => {
        mcapBytes.push(((await downloads.trials.export({ trialId, format: "mcap" })).body as Uint8Array).length);
      }, sampledBySize),
      2000,
    );
    console.log(`  (sizes: ${[0, 1, 2].map((i) => `${(mcapBytes[i * RUNS]! / 1e6).toFixed(1)} MB`).join(", ")})`);
  }

  console.log(
    `\nMachine load after (1, 5, 15 min): ${(await Bun.file("/proc/loadavg").text()).split(" ").slice(0, 3).join(" ")}`,
  );
} finally {
  await close();
  await database.stop();
}
