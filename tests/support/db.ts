import { inject } from "vitest";
import postgres from "postgres";
import { createDatabase, type Database } from "../../src/store/client";
import { experiments, studies, trials, user } from "../../src/store/schema";
import { withDatabase } from "../../src/store/url";

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

/** A rehearsal trial in a study and experiment of its own, straight in the database: for the event store's tests. */
export async function bareTrial(db: Database): Promise<string> {
  const [study] = await db.insert(studies).values({ title: "S" }).returning();
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId: study!.id, name: "E", robotId: "sim" })
    .returning();
  const [trial] = await db
    .insert(trials)
    .values({ studyId: study!.id, experimentId: experiment!.id, isRehearsal: true })
    .returning();
  return trial!.id;
}

/** A wizard straight in the database (no account, no study role): an actor the event store's rows can name. */
export async function bareWizard(db: Database): Promise<string> {
  const id = crypto.randomUUID();
  await db.insert(user).values({ id, name: "Wizard", email: `${id}@example.org` });
  return id;
}
