// Python tools the tests use as references (pympi for ELAN, moto as an S3
// server), installed from PyPI into .tmp/python at pinned versions, never
// into the machine's own Python.
import { spawn, spawnSync, type ChildProcess } from "node:child_process";
import { mkdirSync } from "node:fs";
import { join, resolve } from "node:path";
import { freePort } from "../../src/store/embedded";

const target = join(resolve(import.meta.dirname, "..", ".."), ".tmp", "python");
const env = { ...process.env, PYTHONPATH: target };

export function python(args: string[]) {
  return spawnSync("python3", args, { encoding: "utf8", env, timeout: 300_000 });
}

/** Installs `requirement` unless `module` already imports. */
export function ensurePython(module: string, requirement: string) {
  if (python(["-c", `import ${module}`]).status === 0) return;
  mkdirSync(target, { recursive: true });
  const install = python([
    "-m",
    "pip",
    "install",
    "--quiet",
    "--disable-pip-version-check",
    "--target",
    target,
    requirement,
  ]);
  if (install.status !== 0) throw new Error(`Could not install ${requirement} from PyPI: ${install.stderr}`);
}

/** A real S3-compatible server (moto) on loopback, for the storage contract tests. */
export async function startS3Server(): Promise<{ url: string; stop(): void }> {
  ensurePython("moto.server", "moto[server]==5.1.22");
  const port = await freePort();
  const child: ChildProcess = spawn("python3", ["-m", "moto.server", "-H", "127.0.0.1", "-p", String(port)], {
    env,
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
