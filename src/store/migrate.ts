import { migrate } from "drizzle-orm/postgres-js/migrator";
import { join } from "node:path";
import { createDatabase } from "./client";

export const MIGRATIONS_DIR = join(import.meta.dirname, "migrations");

/** Applies the committed SQL migrations that the database has not seen yet. */
export async function migrateDatabase(url: string, migrationsFolder = MIGRATIONS_DIR) {
  const { db, close } = createDatabase(url, { max: 1 });
  try {
    await migrate(db, { migrationsFolder });
  } finally {
    await close();
  }
}
