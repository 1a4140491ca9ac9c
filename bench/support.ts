// Shared pieces of the benchmarks: a throwaway embedded PostgreSQL, and
// percentiles printed the same way everywhere.
import { mkdtemp, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { startEmbeddedPostgres } from "../src/store/embedded";
import type { Database } from "../src/store/client";
import { migrateDatabase } from "../src/store/migrate";

export async function scratchDatabase() {
  const dir = await mkdtemp(join(tmpdir(), "hri-bench-"));
  const server = await startEmbeddedPostgres({ dataDir: dir });
  await migrateDatabase(server.url);
  return {
    url: server.url,
    async stop() {
      await server.stop();
      await rm(dir, { recursive: true, force: true });
    },
  };
}

export function percentile(sorted: number[], p: number): number {
  return sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))]!;
}

/** One line per measurement: count, median, p99, max (milliseconds), and the target. */
export function report(name: string, samples: number[], targetP99Ms?: number) {
  const sorted = [...samples].sort((a, b) => a - b);
  const p99 = percentile(sorted, 99);
  const verdict =
    targetP99Ms === undefined
      ? ""
      : `  target p99 < ${targetP99Ms} ms: ${p99 < targetP99Ms ? "met" : "NOT met"} (ratio ${(p99 / targetP99Ms).toFixed(2)})`;
  console.log(
    `${name.padEnd(58)} n=${String(sorted.length).padStart(6)}  p50=${percentile(sorted, 50).toFixed(3)} ms  p99=${p99.toFixed(3)} ms  max=${sorted.at(-1)!.toFixed(3)} ms${verdict}`,
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
