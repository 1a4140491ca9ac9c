// What a backup file holds, written first into it as manifest.json: the
// migration level, every table with its columns and row count (in the order
// a restore loads them), the sequences, and every media object.
import { z } from "zod";

export const BACKUP_FORMAT = "hristudio-backup";
export const BACKUP_VERSION = 1;
export const MANIFEST_FILE = "manifest.json";

export const tableFile = (table: string) => `database/${table}.copy`;
export const mediaFile = (key: string) => `media/${key}`;

const manifestSchema = z.object({
  format: z.literal(BACKUP_FORMAT),
  version: z.number().int(),
  createdAt: z.string(),
  /** How many of the committed migrations the database had (0 = none), and the last one's name. */
  migrations: z.object({ level: z.number().int().min(0), last: z.string().nullable() }),
  /** In load order: parents before the tables pointing at them. */
  tables: z.array(
    z.object({ name: z.string().min(1), columns: z.array(z.string().min(1)), rows: z.number().int().min(0) }),
  ),
  /** Sequence values as text: they are bigints. */
  sequences: z.array(z.object({ name: z.string().min(1), value: z.string().regex(/^-?\d+$/), called: z.boolean() })),
  media: z.array(z.object({ key: z.string().min(1), size: z.number().int().min(0) })),
});

export type BackupManifest = z.infer<typeof manifestSchema>;

/** Reads manifest.json, refusing plainly what is not a backup or comes from a newer HRIStudio. */
export function parseManifest(text: string): BackupManifest {
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    throw new Error("The backup file's manifest.json is not JSON: the file is damaged or not an HRIStudio backup.");
  }
  const format = (json as { format?: unknown; version?: unknown } | null) ?? {};
  if (format.format !== BACKUP_FORMAT)
    throw new Error("This file is not an HRIStudio backup (its manifest.json does not say so).");
  if (typeof format.version === "number" && format.version > BACKUP_VERSION) {
    throw new Error(
      `This backup was written by a newer HRIStudio (backup format ${format.version}; this copy reads up to ${BACKUP_VERSION}). Update HRIStudio, then restore.`,
    );
  }
  const parsed = manifestSchema.safeParse(json);
  if (!parsed.success) {
    const issue = parsed.error.issues[0]!;
    throw new Error(
      `The backup file's manifest.json is damaged: ${issue.path.join(".") || "(top)"}: ${issue.message}.`,
    );
  }
  return parsed.data;
}

export interface BackupCounts {
  studies: number;
  trials: number;
  events: number;
  recordings: number;
  mediaFiles: number;
  mediaBytes: number;
}

/** The figures a researcher checks after a backup or a restore. */
export function countsOf(manifest: BackupManifest): BackupCounts {
  const rows = (table: string) => manifest.tables.find((t) => t.name === table)?.rows ?? 0;
  return {
    studies: rows("studies"),
    trials: rows("trials"),
    events: rows("trial_events"),
    recordings: rows("media_recordings"),
    mediaFiles: manifest.media.length,
    mediaBytes: manifest.media.reduce((n, m) => n + m.size, 0),
  };
}

export function formatBytes(bytes: number): string {
  const units = ["bytes", "KB", "MB", "GB", "TB"];
  let value = bytes;
  let unit = 0;
  while (value >= 1024 && unit < units.length - 1) {
    value /= 1024;
    unit++;
  }
  return unit === 0 ? `${value} ${units[0]}` : `${value.toFixed(1)} ${units[unit]}`;
}

const plural = (n: number, word: string, words = `${word}s`) => `${n} ${n === 1 ? word : words}`;

export function describeCounts(c: BackupCounts): string {
  return `${plural(c.studies, "study", "studies")}, ${plural(c.trials, "trial")}, ${plural(c.events, "event")}, ${plural(c.recordings, "recording")} (${plural(c.mediaFiles, "media file")}, ${formatBytes(c.mediaBytes)})`;
}
