// `npm run restore`: a backup file into an empty data folder or database.
// It never overwrites: a target holding any row or media object is refused.
// All or nothing: the rows commit only once every media file is stored, and a
// restore that fails or is interrupted before then rolls the rows back and
// removes the media files it wrote.
import postgres from "postgres";
import { MANIFEST_FILE, parseManifest, type BackupManifest } from "@/core/backup/manifest";
import { checkRestoreLevels } from "@/core/backup/migration-level";
import type { MediaStorage } from "../media/storage";
import { BackupReader } from "./archive-reader";
import { appliedLevel, tablesWithRows } from "./catalog";
import { migrateDatabase, openDatabase } from "./database";
import { loadDatabase } from "./load";
import { readJournal, migrateTo } from "./migrations";
import { restoreMedia } from "./media";

export interface RestoreOptions {
  databaseUrl?: string;
  dataDir: string;
  media: { storage: MediaStorage; where: string };
  file: string;
  progress: (line: string) => void;
  /** Aborted (Ctrl+C, a service manager's stop): the restore stops and undoes what it wrote. */
  signal?: AbortSignal;
}

export async function restore(
  options: RestoreOptions,
): Promise<{ manifest: BackupManifest; into: string; migration: string }> {
  const reader = await BackupReader.open(options.file);
  const manifest = parseManifest((await reader.bytes(MANIFEST_FILE)).toString("utf8"));
  const journal = readJournal();
  const present = await options.media.storage.list("");
  if (present.length) {
    throw new Error(
      `${options.media.where} already holds ${present.length} media files: restore only into an empty one, so nothing is overwritten.`,
    );
  }
  const database = await openDatabase({
    databaseUrl: options.databaseUrl,
    dataDir: options.dataDir,
    purpose: "restore",
  });
  const sql = postgres(database.url, { max: 1, onnotice: () => {} });
  const signal = options.signal ?? new AbortController().signal;
  const written: string[] = [];
  let loading = false;
  let committed = false;
  try {
    const full = await tablesWithRows(sql);
    if (full.length) {
      throw new Error(
        `${capitalised(database.where)} already holds data (in ${full.join(", ")}). Restore only into a new, empty data folder or database, so nothing is overwritten.`,
      );
    }
    checkRestoreLevels(journal, manifest.migrations, await appliedLevel(sql, journal));
    signal.throwIfAborted();
    loading = true;
    options.progress(
      `Restoring into ${database.where}: the schema as the backup had it (${manifest.migrations.last ?? "none"})…`,
    );
    await migrateTo(database.url, manifest.migrations.level);
    await loadDatabase(sql, reader, manifest, options.progress, signal, () =>
      restoreMedia(options.media.storage, reader, manifest.media, options.progress, written, signal),
    );
    committed = true;
    if (manifest.migrations.level < journal.length) {
      options.progress(`Migrating from ${manifest.migrations.last ?? "nothing"} up to ${journal.at(-1)!.tag}…`);
      await migrateDatabase(database.url);
    }
    return { manifest, into: database.where, migration: journal.at(-1)!.tag };
  } catch (error) {
    if (committed) throw error;
    for (const key of written) await options.media.storage.remove(key);
    const reason = signal.aborted
      ? (signal.reason as Error).message
      : error instanceof Error
        ? error.message
        : String(error);
    if (!loading) throw signal.aborted ? new Error(`${reason} Nothing was restored.`) : error;
    const undone = written.length
      ? `the rows loaded so far were rolled back and the ${written.length} media files written so far removed`
      : "the rows loaded so far were rolled back";
    throw new Error(`${reason} Nothing was restored: ${undone}.`);
  } finally {
    await sql.end({ timeout: 5 });
    await database.close();
  }
}

const capitalised = (text: string) => text.charAt(0).toUpperCase() + text.slice(1);
