// Which PostgreSQL a backup or restore talks to: DATABASE_URL when set; else
// the embedded one of the data folder, reached where the running platform
// left it (its postmaster.pid names the port) or started for the while.
// The one file here that uses the database layer, so a move of it touches only this.
import { existsSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { connectionLost } from "@/store/client";
import { startEmbeddedPostgres } from "@/store/embedded";
import { migrateDatabase, MIGRATIONS_DIR } from "@/store/migrate";
import { connectionUrl } from "@/store/url";

export { connectionLost, migrateDatabase, MIGRATIONS_DIR };

export interface OpenDatabase {
  url: string;
  /** Where, in the researcher's words, for messages. */
  where: string;
  /** Stops the PostgreSQL started for this command, if one was. */
  close(): Promise<void>;
}

const nothingToStop = async () => {};

function alive(pid: number): boolean {
  try {
    process.kill(pid, 0);
    return true;
  } catch (error) {
    return (error as NodeJS.ErrnoException).code === "EPERM";
  }
}

/** The URL of the embedded PostgreSQL running on this data folder, or null when none runs. */
export function runningEmbeddedUrl(dataDir: string): string | null {
  const pidFile = join(dataDir, "postgres", "postmaster.pid");
  if (!existsSync(pidFile)) return null;
  // postmaster.pid: line 1 the server's pid, line 4 its port.
  const lines = readFileSync(pidFile, "utf8").split("\n");
  const pid = Number.parseInt(lines[0] ?? "", 10);
  const port = Number.parseInt(lines[3] ?? "", 10);
  if (!Number.isFinite(pid) || !Number.isFinite(port) || !alive(pid)) return null;
  const password = readFileSync(join(dataDir, "postgres-password"), "utf8").trim();
  return connectionUrl({ user: "hristudio", password, host: "127.0.0.1", port, database: "hristudio" });
}

export async function openDatabase(options: {
  databaseUrl?: string;
  dataDir: string;
  purpose: "backup" | "restore";
}): Promise<OpenDatabase> {
  if (options.databaseUrl) {
    const u = new URL(options.databaseUrl);
    return {
      url: options.databaseUrl,
      where: `the database ${u.pathname.slice(1)} on ${u.host} (DATABASE_URL)`,
      close: nothingToStop,
    };
  }
  const pgDir = join(options.dataDir, "postgres");
  const running = runningEmbeddedUrl(options.dataDir);
  if (running) return { url: running, where: `the running database in ${pgDir}`, close: nothingToStop };
  if (options.purpose === "backup" && !existsSync(join(pgDir, "PG_VERSION"))) {
    throw new Error(
      `There is no database in ${options.dataDir}: nothing to back up. Set HRI_DATA_DIR to the data folder that \`npm start\` uses, or DATABASE_URL to the database.`,
    );
  }
  const server = await startEmbeddedPostgres({ dataDir: options.dataDir });
  return { url: server.url, where: `the database in ${pgDir}`, close: () => server.stop() };
}
