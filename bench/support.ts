// Shared pieces of the benchmarks: a throwaway embedded PostgreSQL, and
// percentiles printed the same way everywhere, each beside the floor: what a
// bare commit costs on the same database in the same run, the limit any path
// that commits before it answers can come near but not beat.
import { mkdtemp, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import postgres from "postgres";
import { startEmbeddedPostgres } from "../src/store/embedded";
import type { Database } from "../src/store/client";
import { migrateDatabase } from "../src/store/migrate";

export async function scratchDatabase() {
  const dir = await mkdtemp(join(tmpdir(), "hri-bench-"));
  const server = await startEmbeddedPostgres({ dataDir: dir });
  await migrateDatabase(server.url);
  floor = await bareCommit(server.url);
  console.log(`${"floor: a bare insert + commit on this database".padEnd(58)} ${floorText(floor.busy)}`);
  console.log(`${`floor: the same, each after ${IDLE_MS} ms with nothing to do`.padEnd(58)} ${floorText(floor.idle)}`);
  return {
    url: server.url,
    async stop() {
      await server.stop();
      await rm(dir, { recursive: true, force: true });
    },
  };
}

const FLOOR_COMMITS = 200;
/** Commits after a pause, as a wizard's pace or a time limit has them: fewer, each IDLE_MS apart. */
const IDLE_COMMITS = 100;
const IDLE_MS = 50;
/** The bench's own database's bare commit, once measured: every figure after it is printed beside it. */
let floor: { busy: number[]; idle: number[] } | undefined;

/**
 * A one-row insert and its commit on one connection: FLOOR_COMMITS back to
 * back, then IDLE_COMMITS each after IDLE_MS with nothing to do. The second is
 * the floor of a paced path: on this machine a commit after a pause of 5 ms or
 * more costs two to three times one right after another (the processes and the
 * disk woken again), so a path that commits at a wizard's pace cannot come
 * near the first. The table is a real one, dropped after: a temporary table's
 * commit writes no WAL and so skips the flush that is the floor.
 */
async function bareCommit(url: string): Promise<{ busy: number[]; idle: number[] }> {
  const sql = postgres(url, { max: 1, onnotice: () => {} });
  await sql`create table bench_floor (n integer)`;
  const commits = async (count: number, pauseMs: number) => {
    const samples: number[] = [];
    for (let i = -20; i < count; i++) {
      if (pauseMs) await new Promise((r) => setTimeout(r, pauseMs));
      const started = performance.now();
      await sql`insert into bench_floor values (${i})`;
      // The first few warm the connection and the plan; they are not counted.
      if (i >= 0) samples.push(performance.now() - started);
    }
    return samples.sort((a, b) => a - b);
  };
  const busy = await commits(FLOOR_COMMITS, 0);
  const idle = await commits(IDLE_COMMITS, IDLE_MS);
  await sql`drop table bench_floor`;
  await sql.end();
  return { busy, idle };
}

function floorText(sorted: number[]) {
  return `n=${String(sorted.length).padStart(6)}  p50=${percentile(sorted, 50).toFixed(3)} ms  p99=${percentile(sorted, 99).toFixed(3)} ms`;
}

/** The figure at rank floor(p% × n) counted from 0, erring high: with 100 figures the p99 is the slowest. */
export function percentile(sorted: number[], p: number): number {
  return sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))]!;
}

/** Fewer figures than this have no p99 worth the name: their line gives the median and the slowest only. */
const P99_FROM = 100;

/**
 * One line per measurement: count, median, p99 (from 100 figures), max (milliseconds), the target, and the
 * floors (back to back, and after a pause) when the bench has a database.
 */
export function report(name: string, samples: number[], targetP99Ms?: number) {
  const sorted = [...samples].sort((a, b) => a - b);
  const p99 = percentile(sorted, 99);
  const quoted = sorted.length >= P99_FROM;
  const verdict =
    targetP99Ms === undefined
      ? ""
      : quoted
        ? `  target p99 < ${targetP99Ms} ms: ${p99 < targetP99Ms ? "met" : "NOT met"} (ratio ${(p99 / targetP99Ms).toFixed(2)})`
        : `  target p99 < ${targetP99Ms} ms: not measured (n < ${P99_FROM})`;
  console.log(
    `${name.padEnd(58)} n=${String(sorted.length).padStart(6)}  p50=${percentile(sorted, 50).toFixed(3)} ms  ${quoted ? `p99=${p99.toFixed(3)} ms  ` : ""}max=${sorted.at(-1)!.toFixed(3)} ms${verdict}${floor ? `  floor p50=${percentile(floor.busy, 50).toFixed(3)} p99=${percentile(floor.busy, 99).toFixed(3)} ms, after ${IDLE_MS} ms idle p50=${percentile(floor.idle, 50).toFixed(3)} p99=${percentile(floor.idle, 99).toFixed(3)} ms` : ""}`,
  );
}

/**
 * A trial's log of unscripted lines as rows of trial_events: started, then
 * each line requested, dispatched and completed, then completed; `relMsOf`
 * spaces the events from t0.
 */
export function unscriptedLog(trialId: string, count: number, t0: Date, relMsOf: (i: number) => number) {
  return Array.from({ length: count }, (_, i) => {
    const relMs = relMsOf(i);
    const actionId = `a${Math.floor(i / 3)}`;
    const body =
      i === 0
        ? { type: "trial.started" }
        : i === count - 1
          ? { type: "trial.completed" }
          : [
              {
                type: "action.requested",
                stepId: null,
                actionId,
                actionType: "say",
                parameters: { text: `Line ${i}` },
                scripted: false,
                deviation: "unscripted",
              },
              { type: "action.dispatched", actionId },
              { type: "action.completed", actionId },
            ][i % 3]!;
    return {
      trial_id: trialId,
      seq: i + 1,
      type: body.type,
      server_time: new Date(t0.getTime() + relMs).toISOString(),
      rel_ms: relMs,
      actor_id: null,
      step_id: null,
      action_id: "actionId" in body ? body.actionId : null,
      payload: JSON.stringify(body),
      deviation: "deviation" in body,
    };
  });
}

/** Stores a seeded log (unscriptedLog's rows) in batches: one statement carries at most 65,535 parameters. */
export async function insertLog(db: Database, rows: ReturnType<typeof unscriptedLog>) {
  const sql = db.$client;
  for (let start = 0; start < rows.length; start += 5000)
    await sql`insert into trial_events ${sql(rows.slice(start, start + 5000))}`;
}
