// One real PostgreSQL for the whole run, in a fresh folder; every test file
// gets its own database cloned from a migrated template.
import type { TestProject } from "vitest/node";
import { mkdtemp, rm } from "node:fs/promises";
import { join } from "node:path";
import postgres from "postgres";
import { startEmbeddedPostgres } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { withDatabase } from "../../src/store/url";

export const TEMPLATE_DB = "hristudio_template";

declare module "vitest" {
  export interface ProvidedContext {
    databaseUrl: string;
  }
}

export default async function setup(project: TestProject) {
  await import("node:fs/promises").then((fs) => fs.mkdir(".tmp", { recursive: true }));
  const dataDir = await mkdtemp(join(process.cwd(), ".tmp", "test-pg-"));
  const server = await startEmbeddedPostgres({ dataDir });
  const admin = postgres(server.url, { max: 1, onnotice: () => {} });
  await admin.unsafe(`CREATE DATABASE ${TEMPLATE_DB}`);
  await admin.end();
  await migrateDatabase(withDatabase(server.url, TEMPLATE_DB));
  project.provide("databaseUrl", server.url);
  return async () => {
    await server.stop();
    await rm(dataDir, { recursive: true, force: true });
  };
}
