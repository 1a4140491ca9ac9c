// `npm start`: the whole platform on one machine. PostgreSQL (embedded unless
// DATABASE_URL is set), migrations, the demo seed, then the web app.
import { spawn, type ChildProcess } from "node:child_process";
import { mkdirSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { readConfig } from "../server/config";
import { createDatabase } from "../server/db/client";
import { freePort, startEmbeddedPostgres, type EmbeddedDatabase } from "../server/db/embedded";
import { migrateDatabase } from "../server/db/migrate";
import { seedDemo, type DemoAccount } from "../server/seed/demo";
import { buildIfChanged, nextBin } from "./build";
import { rememberChildren, stopOrphanedChildren } from "./children";
import { authSecret } from "./secret";

const root = resolve(import.meta.dirname, "..", "..");
const dev = process.argv.includes("--dev") || process.env.npm_lifecycle_event === "dev";
const log = (line: string) => console.log(`[hristudio] ${line}`);

async function main() {
  const config = readConfig();
  const dataDir = resolve(root, config.HRI_DATA_DIR);
  mkdirSync(dataDir, { recursive: true });
  const orphans = stopOrphanedChildren(dataDir);
  if (orphans.length) log(`Stopped processes left by an earlier start (${orphans.join(", ")}).`);

  let embedded: EmbeddedDatabase | null = null;
  let databaseUrl = config.DATABASE_URL;
  if (!databaseUrl) {
    log(`Starting the embedded PostgreSQL (data in ${join(dataDir, "postgres")})…`);
    embedded = await startEmbeddedPostgres({ dataDir, onLog: (l) => l.startsWith("Stopped") && log(l) });
    databaseUrl = embedded.url;
  }
  const children: ChildProcess[] = [];
  let stopping = false;
  const stop = async (code: number) => {
    if (stopping) return;
    stopping = true;
    log("Stopping…");
    for (const child of children) child.kill("SIGTERM");
    await embedded?.stop();
    process.exit(code);
  };
  process.on("SIGINT", () => void stop(0));
  process.on("SIGTERM", () => void stop(0));

  await migrateDatabase(databaseUrl);
  log("Database is up to date.");

  const port = config.PORT ?? (await firstFreePort(3000));
  const baseURL = config.BETTER_AUTH_URL ?? `http://${config.HOST === "0.0.0.0" ? "localhost" : config.HOST}:${port}`;
  const secret = authSecret(dataDir, config.BETTER_AUTH_SECRET);

  const seedWanted = config.HRI_SEED_DEMO ?? !config.DATABASE_URL;
  if (seedWanted) {
    const { db, close } = createDatabase(databaseUrl, { max: 2 });
    const accounts = await seedDemo(db, config.HRI_DEMO_PASSWORD);
    await close();
    if (accounts) printDemoAccounts(accounts, dataDir);
  }

  if (!dev && !buildIfChanged(root, log)) return stop(1);
  const runtimePort = config.HRI_RUNTIME_PORT === 3001 ? await firstFreePort(3001) : config.HRI_RUNTIME_PORT;
  const shared = { DATABASE_URL: databaseUrl, BETTER_AUTH_SECRET: secret, HRI_RUNTIME_PORT: String(runtimePort) };
  const remember = () => rememberChildren(dataDir, children.map((c) => c.pid!).filter(Boolean));

  // The trial runtime is restarted if it dies: trials rebuild from their events.
  const startRuntime = () => {
    const runtime = spawn(process.execPath, ["run", join(root, "src", "runtime", "main.ts")], {
      cwd: root,
      stdio: ["ignore", "inherit", "inherit"],
      env: { ...process.env, ...shared },
    });
    children.push(runtime);
    remember();
    runtime.on("exit", (code, signal) => {
      children.splice(children.indexOf(runtime), 1);
      if (stopping) return;
      log(`The trial runtime stopped (${signal ?? `exit code ${code}`}); restarting it.`);
      setTimeout(startRuntime, 500);
    });
  };
  startRuntime();

  const web = spawn("node", [nextBin(root), dev ? "dev" : "start", "-H", config.HOST, "-p", String(port)], {
    cwd: root,
    stdio: ["ignore", "inherit", "inherit"],
    env: { ...process.env, ...shared, BETTER_AUTH_URL: baseURL, NEXT_TELEMETRY_DISABLED: "1" },
  });
  children.push(web);
  remember();
  web.on("exit", (code) => {
    if (!stopping) {
      log(`The web app stopped (exit code ${code}).`);
      void stop(code ?? 1);
    }
  });
  log(`HRIStudio is running at ${baseURL}  (press Ctrl+C to stop)`);
}

async function firstFreePort(preferred: number): Promise<number> {
  const { createServer } = await import("node:net");
  const free = await new Promise<boolean>((ok) => {
    const s = createServer();
    s.once("error", () => ok(false));
    s.listen(preferred, "127.0.0.1", () => s.close(() => ok(true)));
  });
  return free ? preferred : freePort();
}

function printDemoAccounts(accounts: DemoAccount[], dataDir: string) {
  const lines = [
    "",
    "  Demo accounts (for trying HRIStudio only: do not use them for real studies):",
    ...accounts.map(
      (a) => `    ${a.email.padEnd(28)} ${a.password.padEnd(14)} ${a.systemRole}${a.studyRole ? `, ${a.studyRole} of the demo study` : ""}`,
    ),
    `  They are printed once; a copy is in ${join(dataDir, "demo-accounts.txt")}.`,
    "",
  ];
  writeFileSync(join(dataDir, "demo-accounts.txt"), lines.join("\n"), { mode: 0o600 });
  console.log(lines.join("\n"));
}

main().catch((error) => {
  console.error(`[hristudio] Could not start: ${error instanceof Error ? error.message : String(error)}`);
  process.exit(1);
});
