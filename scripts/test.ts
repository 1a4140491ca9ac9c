// `npm test`: the whole suite in one vitest run, against a real PostgreSQL
// and Debian's Chromium. Installs Chromium first when it can (root + apt).
import { spawnSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { buildIfChanged } from "../src/launcher/build";
import { findChromium } from "../tests/support/chromium";

const root = resolve(import.meta.dirname, "..");
const log = (line: string) => console.log(`[test] ${line}`);

function ensureChromium() {
  if (findChromium()) return;
  const canApt = process.getuid?.() === 0 && existsSync("/usr/bin/apt-get");
  if (!canApt) {
    console.error("[test] Chromium is needed for the browser tests. Install Debian's `chromium` package (or set HRI_CHROMIUM to a Chromium binary) and run again.");
    process.exit(1);
  }
  log("Installing Debian's chromium for the browser tests…");
  const env = { ...process.env, DEBIAN_FRONTEND: "noninteractive" };
  spawnSync("apt-get", ["update", "-qq"], { stdio: "inherit", env });
  const installed = spawnSync("apt-get", ["install", "-y", "-qq", "--no-install-recommends", "chromium", "fonts-dejavu-core"], { stdio: "inherit", env });
  if (installed.status !== 0 || !findChromium()) {
    console.error("[test] Could not install chromium with apt-get.");
    process.exit(1);
  }
}

ensureChromium();
log("Type-checking…");
const typecheck = spawnSync("node", [join(root, "node_modules", "typescript", "bin", "tsc"), "--noEmit", "-p", root], { cwd: root, stdio: "inherit" });
if (typecheck.status !== 0) process.exit(typecheck.status ?? 1);
if (!buildIfChanged(root, log)) process.exit(1);
mkdirSync(join(root, ".tmp"), { recursive: true });
const report = join(root, ".tmp", "vitest-report.json");
const run = spawnSync(
  "node",
  [join(root, "node_modules", "vitest", "vitest.mjs"), "run", "--reporter=default", "--reporter=json", `--outputFile.json=${report}`, ...process.argv.slice(2)],
  { cwd: root, stdio: "inherit", env: { ...process.env, NEXT_TELEMETRY_DISABLED: "1" } },
);
if (existsSync(report)) {
  const r = JSON.parse(readFileSync(report, "utf8")) as { numPassedTests: number; numFailedTests: number; numPendingTests: number; numTodoTests: number };
  console.log(`${r.numPassedTests} passed, ${r.numFailedTests} failed, ${r.numPendingTests + r.numTodoTests} skipped`);
}
process.exit(run.status ?? 1);
