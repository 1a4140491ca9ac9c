// Freezing a PostgreSQL of a test's own (every process SIGSTOPped, as a hung
// server would be) and thawing it. Only ever a server the test started itself
// (startEmbeddedPostgres on its own data folder): freezing the suite's shared
// one would stop every other test.
import { execFileSync } from "node:child_process";
import { readFile } from "node:fs/promises";
import { join } from "node:path";

/** The postmaster and every backend it started: the whole database server of the data folder. */
async function postgresProcesses(dataDir: string): Promise<number[]> {
  const postmaster = Number((await readFile(join(dataDir, "postgres", "postmaster.pid"), "utf8")).split("\n")[0]);
  const children = execFileSync("ps", ["-o", "pid=", "--ppid", String(postmaster)], { encoding: "utf8" })
    .split("\n")
    .map((l) => Number(l.trim()))
    .filter((pid) => pid > 0);
  return [postmaster, ...children];
}

export async function signalDatabase(dataDir: string, signal: "SIGSTOP" | "SIGCONT") {
  for (const pid of await postgresProcesses(dataDir)) process.kill(pid, signal);
}
