import { inject } from "vitest";
import postgres from "postgres";
import { createDatabase } from "../../src/data/client";
import { withDatabase } from "../../src/data/url";

const TEMPLATE_DB = "hristudio_template";

/** The URL of the run's PostgreSQL server (its maintenance database). */
export function serverUrl(): string {
  return inject("databaseUrl");
}

/** A new, migrated, empty database for one test file. */
export async function freshDatabaseUrl(template: string | null = TEMPLATE_DB): Promise<string> {
  const name = `t_${crypto.randomUUID().replaceAll("-", "")}`;
  const admin = postgres(serverUrl(), { max: 1, onnotice: () => {} });
  try {
    await admin.unsafe(template ? `CREATE DATABASE ${name} TEMPLATE ${template}` : `CREATE DATABASE ${name}`);
  } finally {
    await admin.end();
  }
  return withDatabase(serverUrl(), name);
}

export async function freshDatabase() {
  const url = await freshDatabaseUrl();
  return { url, ...createDatabase(url, { max: 4 }) };
}
