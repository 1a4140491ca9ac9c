// `npm run backup`: the database and every media object into one file.
import { mkdir } from "node:fs/promises";
import { dirname } from "node:path";
import postgres from "postgres";
import { BACKUP_FORMAT, BACKUP_VERSION, MANIFEST_FILE, type BackupManifest } from "@/core/backup/manifest";
import type { MediaStorage } from "../media/storage";
import { BackupWriter } from "./archive";
import { openDatabase } from "./database";
import { dumpDatabase } from "./dump";
import { dumpMedia } from "./media";

export interface BackupOptions {
  databaseUrl?: string;
  dataDir: string;
  media: MediaStorage;
  out: string;
  progress: (line: string) => void;
}

export async function backup(
  options: BackupOptions,
): Promise<{ manifest: BackupManifest; bytes: number; from: string }> {
  const database = await openDatabase({
    databaseUrl: options.databaseUrl,
    dataDir: options.dataDir,
    purpose: "backup",
  });
  const sql = postgres(database.url, { max: 1, onnotice: () => {} });
  await mkdir(dirname(options.out), { recursive: true });
  const writer = await BackupWriter.create(options.out);
  try {
    options.progress(`Backing up ${database.where}…`);
    const part = await dumpDatabase(sql, writer, options.progress);
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
    return { manifest, bytes: await writer.finish(), from: database.where };
  } catch (error) {
    await writer.abandon();
    throw error;
  } finally {
    await sql.end({ timeout: 5 });
    await database.close();
  }
}
