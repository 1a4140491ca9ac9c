// `npm run backup`: the database and every media object into one file.
import { mkdir } from "node:fs/promises";
import { dirname } from "node:path";
import postgres from "postgres";
import { BACKUP_FORMAT, BACKUP_VERSION, MANIFEST_FILE, type BackupManifest } from "@/core/backup/manifest";
import type { MediaStorage } from "../media/storage";
import { BackupWriter, type BackupTarget } from "./archive";
import { connectionLost, openDatabase } from "./database";
import { dumpDatabase } from "./dump";
import { dumpMedia } from "./media";

export interface BackupOptions {
  databaseUrl?: string;
  dataDir: string;
  media: MediaStorage;
  target: BackupTarget;
  progress: (line: string) => void;
  /** Aborted (Ctrl+C, a service manager's stop): the backup stops at once and its partial file is removed. */
  signal?: AbortSignal;
}

export async function backup(
  options: BackupOptions,
): Promise<{ manifest: BackupManifest; bytes: number; from: string; file: string }> {
  const database = await openDatabase({
    databaseUrl: options.databaseUrl,
    dataDir: options.dataDir,
    purpose: "backup",
  });
  const sql = postgres(database.url, { max: 1, onnotice: () => {} });
  // Stops the work wherever it is waiting: an interruption, or a write that failed inside a COPY.
  const halt = new AbortController();
  const halted = new Promise<never>((_, reject) =>
    halt.signal.addEventListener("abort", () => reject(halt.signal.reason)),
  );
  const interrupted = () => halt.abort(options.signal!.reason);
  options.signal?.addEventListener("abort", interrupted);
  let writer: BackupWriter | undefined;
  const work = (async () => {
    await mkdir("file" in options.target ? dirname(options.target.file) : options.target.folder, { recursive: true });
    halt.signal.throwIfAborted(); // Stopped while the database was being opened: no file at all.
    writer = BackupWriter.create(options.target);
    options.progress(`Backing up ${database.where} into ${writer.path}…`);
    const part = await dumpDatabase(sql, writer, options.progress, (error) => halt.abort(error));
    // After the database's moment, so every recording it lists is already in the store.
    const media = await dumpMedia(options.media, writer, options.progress);
    const manifest: BackupManifest = {
      format: BACKUP_FORMAT,
      version: BACKUP_VERSION,
      createdAt: new Date().toISOString(),
      ...part,
      media,
    };
    await writer.add(MANIFEST_FILE, [new TextEncoder().encode(JSON.stringify(manifest, null, 2))]);
    return { manifest, bytes: writer.finish(), from: database.where, file: writer.path };
  })();
  try {
    if (options.signal?.aborted) interrupted();
    return await Promise.race([work, halted]);
  } catch (error) {
    if (halt.signal.aborted) {
      work.catch(() => {}); // Still reading: it ends as the connection is closed here; its failure is this one.
      await sql.end({ timeout: 0 });
    }
    const reason = connectionLost(error)
      ? "The connection to the database was lost (was PostgreSQL stopped or restarted?)."
      : error instanceof Error
        ? error.message
        : String(error);
    if (!writer) throw new Error(reason);
    writer.abandon();
    throw new Error(`${reason} The unfinished file ${writer.path}.part was removed: no backup was written.`);
  } finally {
    options.signal?.removeEventListener("abort", interrupted);
    await sql.end({ timeout: 5 });
    await database.close();
  }
}
