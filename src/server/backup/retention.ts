// `npm run backup -- --keep N`: after a backup is written, the older backups
// of its folder beyond the newest N are removed (never a file it did not name).
import { readdir, rm } from "node:fs/promises";
import { join } from "node:path";
import { expiredBackups } from "@/core/backup/naming";

export async function removeExpired(folder: string, keep: number): Promise<string[]> {
  const expired = expiredBackups(await readdir(folder), keep);
  for (const name of expired) await rm(join(folder, name), { force: true });
  return expired;
}
