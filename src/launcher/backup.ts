// `npm run backup [-- --out FILE]`: the database and every recording into one
// file, while the platform runs or not. See README.md, "Backups".
import { join } from "node:path";
import { countsOf, describeCounts, formatBytes } from "@/core/backup/manifest";
import { backup } from "../server/backup/backup";
import { backupContext, typedPath } from "./backup-context";

const context = backupContext("backup");
const args = process.argv.slice(2);
const outAt = args.findIndex((a) => a === "--out" || a === "-o");
if (
  args.some((a) => a === "--help" || a === "-h") ||
  (args.length && outAt !== 0) ||
  (outAt === 0 && args.length !== 2)
) {
  console.log(
    "Usage: npm run backup [-- --out FILE]\nWrites the database and every recording into one file (default: backups/hristudio-<date>-<time>.tar).",
  );
  process.exit(args.some((a) => a === "--help" || a === "-h") ? 0 : 2);
}
const stamp = new Date().toISOString().slice(0, 19).replace("T", "-").replaceAll(":", "");
const out = outAt === 0 ? typedPath(args[1]!) : join(context.root, "backups", `hristudio-${stamp}.tar`);

try {
  const { manifest, bytes, from } = await backup({
    databaseUrl: context.databaseUrl,
    dataDir: context.dataDir,
    media: context.media.storage,
    out,
    progress: context.progress,
  });
  console.log(
    `Backed up ${describeCounts(countsOf(manifest))} from ${from}, at database migration ${manifest.migrations.last ?? "none"}.`,
  );
  console.log(`The backup is ${out} (${formatBytes(bytes)}). Restore it with: npm run restore -- ${out}`);
} catch (error) {
  context.fail(error);
}
