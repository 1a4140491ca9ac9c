// `npm run backup [-- --out FILE|FOLDER] [--keep N]`: the database and every
// recording into one file, while the platform runs or not. See README.md, "Backups".
import { statSync } from "node:fs";
import { join } from "node:path";
import { countsOf, describeCounts, formatBytes } from "@/core/backup/manifest";
import type { BackupTarget } from "../server/backup/archive";
import { backup } from "../server/backup/backup";
import { removeExpired } from "../server/backup/retention";
import { backupContext, interruption, typedPath } from "./backup-context";

const USAGE = `Usage: npm run backup [-- --out FILE|FOLDER] [--keep N]
Writes the database and every recording into one new file: FILE, or a new
hristudio-<date>-<time>.tar in FOLDER (default: backups/). It never replaces a file.
--keep N  then removes all but the newest N backups of that folder (those named hristudio-….tar).`;

const context = backupContext("backup");

function parse(args: string[]): { out?: string; keep?: number } | null {
  const options: { out?: string; keep?: number } = {};
  for (let i = 0; i < args.length; i += 2) {
    const [flag, value] = [args[i], args[i + 1]];
    if (value === undefined) return null;
    if ((flag === "--out" || flag === "-o") && options.out === undefined) options.out = value;
    else if (flag === "--keep" && options.keep === undefined && /^[1-9]\d*$/.test(value)) options.keep = Number(value);
    else return null;
  }
  return options;
}

const args = process.argv.slice(2);
const help = args.some((a) => a === "--help" || a === "-h");
const options = help ? null : parse(args);
if (!options) {
  console.log(USAGE);
  process.exit(help ? 0 : 2);
}
const out = options.out === undefined ? join(context.root, "backups") : typedPath(options.out);
const intoFolder =
  options.out === undefined || options.out.endsWith("/") || statSync(out, { throwIfNoEntry: false })?.isDirectory();
if (options.keep !== undefined && !intoFolder)
  context.fail(
    new Error("--keep removes older backups from a folder: give --out a folder (or leave it out), not a file."),
  );
const target: BackupTarget = intoFolder ? { folder: out, now: new Date() } : { file: out };

try {
  const { manifest, bytes, from, file } = await backup({
    databaseUrl: context.databaseUrl,
    dataDir: context.dataDir,
    media: context.media.storage,
    target,
    progress: context.progress,
    signal: interruption(),
  });
  console.log(
    `Backed up ${describeCounts(countsOf(manifest))} from ${from}, at database migration ${manifest.migrations.last ?? "none"}.`,
  );
  console.log(`The backup is ${file} (${formatBytes(bytes)}). Restore it with: npm run restore -- ${file}`);
  if (options.keep !== undefined && "folder" in target) {
    const removed = await removeExpired(target.folder, options.keep);
    if (removed.length)
      console.log(`Removed ${removed.length} older backups (--keep ${options.keep}): ${removed.join(", ")}.`);
  }
} catch (error) {
  context.fail(error);
}
