#!/usr/bin/env node
// Entry point of `npm start`, `npm test` and the other commands below. It needs only Node and npm:
// it installs the project's dependencies with bun (fetched from npm) when the
// lockfile changed, then hands over to the bun script for the command.
import { spawn, spawnSync } from "node:child_process";
import { createHash } from "node:crypto";
import { existsSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const root = join(dirname(fileURLToPath(import.meta.url)), "..");
const pkg = JSON.parse(readFileSync(join(root, "package.json"), "utf8"));
const bunVersion = pkg.packageManager.replace(/^bun@/, "");
const commands = {
  start: "src/launcher/start.ts",
  test: "scripts/test.ts",
  dev: "src/launcher/start.ts",
  bench: "bench/run.ts",
  backup: "src/launcher/backup.ts",
  restore: "src/launcher/restore.ts",
  screenshots: "scripts/screenshots.ts",
};

/** The commands that run the platform until stopped. */
const SERVES = new Set(["start", "dev"]);

const command = process.argv[2];
if (!commands[command]) {
  console.error(`Unknown command "${command}". Use one of: ${Object.keys(commands).join(", ")}.`);
  process.exit(2);
}

const env = { ...process.env, npm_config_nodedir: process.env.npm_config_nodedir ?? "/usr" };

function run(cmd, args) {
  const result = spawnSync(cmd, args, { cwd: root, stdio: "inherit", env });
  if (result.error) throw result.error;
  return result.status ?? 1;
}

function localBun() {
  const candidates = [
    join(root, "node_modules", "@oven", `bun-${process.platform}-${process.arch}`, "bin", "bun"),
    join(root, "node_modules", "@oven", `bun-${process.platform}-${process.arch}-baseline`, "bin", "bun"),
  ];
  return candidates.find((p) => existsSync(p));
}

function installIfNeeded() {
  const stampFile = join(root, "node_modules", ".hristudio-install");
  const wanted = createHash("sha256")
    .update(readFileSync(join(root, "package.json")))
    .update(readFileSync(join(root, "bun.lock")))
    .digest("hex");
  if (existsSync(stampFile) && readFileSync(stampFile, "utf8") === wanted && localBun()) return;
  console.log("Installing dependencies with bun (first run, or the lockfile changed)…");
  const bun = localBun();
  const status = bun
    ? run(bun, ["install", "--frozen-lockfile"])
    : run("npx", ["--yes", `bun@${bunVersion}`, "install", "--frozen-lockfile"]);
  if (status !== 0) {
    console.error("Dependency installation failed; see the messages above.");
    process.exit(status);
  }
  writeFileSync(stampFile, wanted);
}

installIfNeeded();
const bun = localBun();
if (!bun) {
  console.error("bun was not installed into node_modules; delete node_modules and try again.");
  process.exit(1);
}
const args = ["run", commands[command], ...process.argv.slice(3)];
if (!SERVES.has(command)) process.exit(run(bun, args));
// The platform runs in a process group of its own, so Ctrl+C reaches the launcher alone, passed on from
// here: the terminal would otherwise send it to every process at once, and PostgreSQL would stop under
// the runtime and the web app while they were still writing (the launcher stops them first).
const platform = spawn(bun, args, { cwd: root, stdio: ["ignore", "inherit", "inherit"], env, detached: true });
for (const signal of ["SIGINT", "SIGTERM", "SIGHUP"]) process.on(signal, () => platform.kill(signal));
platform.on("exit", (code) => process.exit(code ?? 1));
