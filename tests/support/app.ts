// Runs the real launcher (`src/launcher/start.ts` under bun), as `npm start`
// does, with its own data folder and port: embedded PostgreSQL, migrations,
// demo seed and the built web app.
import { spawn, type ChildProcess } from "node:child_process";
import { readFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { freePort } from "../../src/store/embedded";
import { scratchFolder } from "./scratch";

const root = resolve(import.meta.dirname, "..", "..");
export const BUN = join(root, "node_modules", "@oven", `bun-${process.platform}-${process.arch}`, "bin", "bun");
export const DEMO_PASSWORD = "demo-password-for-tests";
/** How long the tests' simulated robots take to say one character: a quick talker. */
export const SIMULATOR_MS_PER_CHAR = 5;

export interface RunningApp {
  url: string;
  runtimeUrl: string;
  /** The simulated robot's rosbridge socket, for a test that listens as the robot hears. */
  simulatorUrl: string;
  dataDir: string;
  process: ChildProcess;
  output: () => string;
  /** What the processes wrote to stderr alone. */
  errors: () => string;
  /** SIGINT to the launcher: it stops the web app and PostgreSQL cleanly. */
  stop(): Promise<void>;
  /**
   * Ctrl+C in the terminal the app was started from: SIGINT to every process of its foreground group;
   * resolves once every process writing to its output has ended.
   */
  interrupt(): Promise<void>;
  /**
   * kill -9, as a crash would: of the launcher alone (its web app and
   * PostgreSQL run on as orphans), or of every process it started.
   */
  crash(what: "launcher" | "everything"): Promise<void>;
}

export function newDataDir(): string {
  return scratchFolder("app-");
}

type StartOptions = {
  dataDir?: string;
  env?: Record<string, string>;
  /** Through `npm start`'s own way in (scripts/bootstrap.mjs) rather than the launcher itself. */
  npmStart?: boolean;
};

/** How many times an app whose port was taken as it started is started again, on other ports. */
const PORT_TAKEN_TRIES = 3;

/**
 * The app on ports the system found free. A port found free can still be taken before the app listens on it
 * (the system hands the same range to every outgoing connection, and to the launcher's own services): the app
 * then stops with EADDRINUSE, and is started again on other ports (in the data folder given, else a new one),
 * unless the test named the web port itself.
 */
export async function startApp(options: StartOptions = {}): Promise<RunningApp> {
  for (let attempt = 1; ; attempt++) {
    try {
      return await startOnce(options, options.dataDir ?? newDataDir());
    } catch (error) {
      // A web port the test gave is its own choice: taken, it is the test's answer, not a race to try again.
      if (attempt === PORT_TAKEN_TRIES || options.env?.PORT || !/EADDRINUSE/.test(String(error))) throw error;
    }
  }
}

async function startOnce(options: StartOptions, dataDir: string): Promise<RunningApp> {
  const port = await freePort();
  const runtimePort = await freePort();
  const simulatorPort = await freePort();
  let output = "";
  let errors = "";
  const [command, args] = options.npmStart
    ? ["node", ["scripts/bootstrap.mjs", "start"]]
    : [BUN, ["run", "src/launcher/start.ts"]];
  // In a process group of its own, as a terminal starts a command.
  const child = spawn(command, args, {
    cwd: root,
    detached: true,
    stdio: ["ignore", "pipe", "pipe"],
    env: {
      ...process.env,
      DATABASE_URL: "",
      HRI_DATA_DIR: dataDir,
      PORT: String(port),
      HRI_RUNTIME_PORT: String(runtimePort),
      HRI_SIMULATOR_PORT: String(simulatorPort),
      HRI_DEMO_PASSWORD: DEMO_PASSWORD,
      HRI_SIGNIN_PER_MINUTE: "1000",
      // A quick talker: a say is completed once said, and the tests' trials need not last as long as speech.
      HRI_SIMULATOR_MS_PER_CHAR: String(SIMULATOR_MS_PER_CHAR),
      ...options.env,
    },
  });
  child.stdout!.on("data", (d) => (output += d));
  child.stderr!.on("data", (d) => {
    output += d;
    errors += d;
  });
  const url = await new Promise<string>((ok, fail) => {
    const timer = setTimeout(() => fail(new Error(`The app did not start in time:\n${output}`)), 120_000);
    child.stdout!.on("data", () => {
      const m = /running at (http:\/\/\S+)/.exec(output);
      if (m) {
        clearTimeout(timer);
        ok(m[1]!);
      }
    });
    child.on("exit", (code) => {
      clearTimeout(timer);
      fail(new Error(`The launcher exited with ${code}:\n${output}`));
    });
  });
  // A web app whose port was taken says so and stops: no use waiting the whole two minutes for it.
  const portTaken = () => /EADDRINUSE/.test(output);
  await waitForHttp(`${url}/api/auth/ok`, portTaken).catch(async (error: Error) => {
    // Why, in the app's own words (a web app that stopped says so in its output).
    const gone = new Promise<void>((ok) => (child.exitCode === null ? child.once("close", () => ok()) : ok()));
    process.kill(-child.pid!, "SIGKILL");
    await gone;
    throw new Error(`${error.message}. The app's output:\n${output.split("\n").slice(-40).join("\n")}`);
  });
  const exited = new Promise<void>((ok) => child.once("exit", () => ok()));
  // Once every process that shares its output (the launcher's children too) has ended.
  const closed = new Promise<void>((ok) => child.once("close", () => ok()));
  return {
    url,
    runtimeUrl: `ws://127.0.0.1:${runtimePort}`,
    simulatorUrl: `ws://127.0.0.1:${simulatorPort}`,
    dataDir,
    process: child,
    output: () => output,
    errors: () => errors,
    async stop() {
      if (child.exitCode === null) child.kill("SIGINT");
      await exited;
    },
    async interrupt() {
      if (child.exitCode === null) process.kill(-child.pid!, "SIGINT");
      await closed;
    },
    async crash(what) {
      process.kill(what === "launcher" ? child.pid! : -child.pid!, "SIGKILL");
      await exited;
    },
  };
}

// Two minutes: a loaded machine can take a minute to start the web app; a stuck one never answers.
async function waitForHttp(url: string, failed: () => boolean = () => false) {
  const deadline = Date.now() + 120_000;
  while (Date.now() < deadline && !failed()) {
    try {
      const res = await fetch(url, { signal: AbortSignal.timeout(5000) });
      if (res.ok) return;
    } catch {
      // Not listening yet, or not answering yet.
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error(`${url} never answered`);
}

/** The pid of the launcher's child running `script` (e.g. "runtime/main.ts"), as the launcher recorded it. */
export function childPid(app: RunningApp, script: string): number {
  const children: Array<{ pid: number }> = JSON.parse(
    readFileSync(join(app.dataDir, "launcher-children.json"), "utf8"),
  );
  const pid = children
    .map((c) => c.pid)
    .find((p) => {
      try {
        return readFileSync(`/proc/${p}/cmdline`, "utf8").includes(script);
      } catch {
        return false;
      }
    });
  if (!pid) throw new Error(`The launcher has no child running ${script}.`);
  return pid;
}
