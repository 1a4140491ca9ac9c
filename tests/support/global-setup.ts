// One real PostgreSQL for the whole run; every test file gets its own database
// cloned from a migrated template. The run writes under a folder of its own
// (see scratch.ts), removed at its end with the server's data in it; one left
// by a run that was killed is removed by the next.
import type { TestProject } from "vitest/node";
import { chmod, mkdir, mkdtemp, readdir, readFile, rm, writeFile } from "node:fs/promises";
import { join } from "node:path";
import postgres from "postgres";
import { startOf } from "../../src/launcher/children";
import { startEmbeddedPostgres } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { withDatabase } from "../../src/store/url";
import { SCRATCH_VARIABLE } from "./scratch";

export const TEMPLATE_DB = "hristudio_template";
const RUNS = join(process.cwd(), ".tmp");
const OWNER = "run-owner.json";

declare module "vitest" {
  export interface ProvidedContext {
    databaseUrl: string;
  }
}

/** Run folders whose run has ended without removing them (killed, or stopped with Ctrl+C). */
async function removeAbandonedRuns() {
  for (const name of (await readdir(RUNS)).filter((n) => n.startsWith("run-"))) {
    const dir = join(RUNS, name);
    const owner = await readFile(join(dir, OWNER), "utf8").then(
      (text) => JSON.parse(text) as { pid: number; started: string },
      () => null,
    );
    if (owner && startOf(owner.pid) === owner.started) continue;
    await rm(dir, { recursive: true, force: true });
  }
}

/** The run's folder: made by the first project's setup, the one torn down last; the others share it. */
async function runFolder(): Promise<{ dir: string; ours: boolean }> {
  const shared = process.env[SCRATCH_VARIABLE];
  if (shared) return { dir: shared, ours: false };
  await mkdir(RUNS, { recursive: true });
  await removeAbandonedRuns();
  const dir = await mkdtemp(join(RUNS, "run-"));
  // PostgreSQL runs as the `postgres` user when we are root: it must reach its folders in here.
  await chmod(dir, 0o755);
  await writeFile(join(dir, OWNER), JSON.stringify({ pid: process.pid, started: startOf(process.pid) }));
  // Workers are started after every setup and inherit this.
  process.env[SCRATCH_VARIABLE] = dir;
  return { dir, ours: true };
}

export default async function setup(project: TestProject) {
  const run = await runFolder();
  const dataDir = await mkdtemp(join(run.dir, "test-pg-"));
  const server = await startEmbeddedPostgres({ dataDir });
  const admin = postgres(server.url, { max: 1, onnotice: () => {} });
  await admin.unsafe(`CREATE DATABASE ${TEMPLATE_DB}`);
  await admin.end();
  await migrateDatabase(withDatabase(server.url, TEMPLATE_DB));
  project.provide("databaseUrl", server.url);
  return async () => {
    await server.stop();
    await rm(run.ours ? run.dir : dataDir, { recursive: true, force: true });
  };
}
