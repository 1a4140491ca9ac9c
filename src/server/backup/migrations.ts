// The committed migrations, and migrating a database to one of their levels
// (a restore first builds the schema the backup was taken from, loads it,
// then migrates up to the current one).
import { readFileSync } from "node:fs";
import { copyFile, mkdir, mkdtemp, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import type { JournalEntry } from "@/core/backup/migration-level";
import { migrateDatabase, MIGRATIONS_DIR } from "./database";

interface Journal {
  entries: JournalEntry[];
}

export function readJournal(folder = MIGRATIONS_DIR): JournalEntry[] {
  return (JSON.parse(readFileSync(join(folder, "meta", "_journal.json"), "utf8")) as Journal).entries;
}

/** Applies the first `level` committed migrations: Drizzle's migrator given a folder holding only those. */
export async function migrateTo(url: string, level: number) {
  const all = JSON.parse(readFileSync(join(MIGRATIONS_DIR, "meta", "_journal.json"), "utf8")) as Journal;
  if (level >= all.entries.length) return migrateDatabase(url);
  if (level === 0) return;
  const folder = await mkdtemp(join(tmpdir(), "hristudio-migrations-"));
  try {
    await mkdir(join(folder, "meta"));
    const entries = all.entries.slice(0, level);
    await writeFile(join(folder, "meta", "_journal.json"), JSON.stringify({ ...all, entries }));
    for (const e of entries) await copyFile(join(MIGRATIONS_DIR, `${e.tag}.sql`), join(folder, `${e.tag}.sql`));
    await migrateDatabase(url, folder);
  } finally {
    await rm(folder, { recursive: true, force: true });
  }
}
