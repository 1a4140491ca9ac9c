// Python tools the tests use as references (pympi reads our ELAN files back,
// moto plays an S3 server): a virtual environment under node_modules/.cache
// with tests/python/requirements.txt installed at its pinned versions, built
// once and again whenever that file changes, never touching the machine's
// own Python. Scripts live in tests/python/.
import { type ChildProcess, spawn, spawnSync } from "node:child_process";
import { createHash } from "node:crypto";
import { existsSync, mkdirSync, readFileSync, rmSync, statSync, writeFileSync } from "node:fs";
import { join, relative, resolve } from "node:path";
import { freePort } from "../../src/store/embedded";

const root = resolve(import.meta.dirname, "..", "..");
const scripts = join(root, "tests", "python");
const requirements = join(scripts, "requirements.txt");
const home = join(root, "node_modules", ".cache", "hristudio-python");
const stamp = join(home, "requirements.sha256");
const python = join(home, "bin", "python");

const MISSING =
  "The tests read some exports back with Python tools, and need Python 3 with venv and pip: python3 was not found. " +
  "Install it (on Debian: apt-get install python3 python3-venv python3-pip) and run the tests again.";

function run(command: string, args: string[], what: string): string {
  const result = spawnSync(command, args, { encoding: "utf8", timeout: 600_000, maxBuffer: 64 * 1024 * 1024 });
  if ((result.error as NodeJS.ErrnoException | undefined)?.code === "ENOENT") throw new Error(MISSING);
  if (result.error) throw new Error(`${what} did not finish: ${result.error.message}`);
  if (result.status !== 0)
    throw new Error(`${what} failed (exit ${result.status}):\n${result.stderr || result.stdout}`);
  return result.stdout;
}

/** One builder at a time across test workers: the others wait for it, then find the environment ready. */
function exclusively(build: () => void) {
  const lock = `${home}.lock`;
  mkdirSync(join(home, ".."), { recursive: true });
  for (;;) {
    try {
      mkdirSync(lock);
      break;
    } catch (error) {
      if ((error as NodeJS.ErrnoException).code !== "EEXIST") throw error;
    }
    // A builder that died leaves its lock behind; an install never takes this long.
    const age = Date.now() - (statSync(lock, { throwIfNoEntry: false })?.mtimeMs ?? Date.now());
    if (age > 15 * 60_000) rmSync(lock, { recursive: true, force: true });
    else Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, 500);
  }
  try {
    build();
  } finally {
    rmSync(lock, { recursive: true, force: true });
  }
}

const current = (wanted: string) => existsSync(stamp) && readFileSync(stamp, "utf8") === wanted;

/** The environment's python, installing the requirements first when they are missing or changed. */
export function pythonEnvironment(): string {
  const wanted = createHash("sha256").update(readFileSync(requirements)).digest("hex");
  if (current(wanted)) return python;
  exclusively(() => {
    if (current(wanted)) return;
    rmSync(home, { recursive: true, force: true });
    run("python3", ["-m", "venv", home], "Creating the tests' Python environment (python3 -m venv)");
    run(
      python,
      ["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "-r", requirements],
      `Installing ${relative(root, requirements)} from PyPI`,
    );
    writeFileSync(stamp, wanted);
  });
  return python;
}

/** Runs tests/python/<script> with `args`; its standard output, or an error with what it wrote on failing. */
export function runPython(script: string, args: string[] = []): string {
  return run(pythonEnvironment(), [join(scripts, script), ...args], `tests/python/${script}`);
}

/** A real S3-compatible server (moto) on loopback, for the storage contract tests. */
export async function startS3Server(): Promise<{ url: string; stop(): void }> {
  const interpreter = pythonEnvironment();
  const port = await freePort();
  const child: ChildProcess = spawn(interpreter, ["-m", "moto.server", "-H", "127.0.0.1", "-p", String(port)], {
    stdio: "ignore",
  });
  const url = `http://127.0.0.1:${port}`;
  for (let i = 0; i < 150; i++) {
    if (
      await fetch(url).then(
        () => true,
        () => false,
      )
    )
      return { url, stop: () => child.kill("SIGKILL") };
    await new Promise((r) => setTimeout(r, 100));
  }
  child.kill("SIGKILL");
  throw new Error("The S3 test server (moto) did not start");
}
