// `npm run restore -- FILE`: a backup into an empty data folder (HRI_DATA_DIR)
// or an empty database (DATABASE_URL), with its recordings. See README.md, "Backups".
import { countsOf, describeCounts } from "@/core/backup/manifest";
import { restore } from "../server/backup/restore";
import { backupContext, interruption, typedPath } from "./backup-context";

const args = process.argv.slice(2);
if (args.length !== 1 || args[0] === "--help" || args[0] === "-h") {
  console.log(
    "Usage: npm run restore -- FILE\nRestores a backup made by `npm run backup` into an empty data folder (HRI_DATA_DIR) or an empty database (DATABASE_URL).",
  );
  process.exit(args[0] === "--help" || args[0] === "-h" ? 0 : 2);
}
const context = backupContext("restore");

try {
  const { manifest, into, migration } = await restore({
    ...context,
    file: typedPath(args[0]!),
    progress: context.progress,
    signal: interruption(),
  });
  console.log(
    `Restored ${describeCounts(countsOf(manifest))}, backed up ${manifest.createdAt}, into ${into}; the database is at migration ${migration}.`,
  );
  console.log("Start the platform with `npm start`.");
} catch (error) {
  context.fail(error);
}
