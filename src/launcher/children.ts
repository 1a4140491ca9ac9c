// Child processes the launcher starts, remembered on disk so that a launcher
// killed with -9 does not leave the next start fighting its orphans for ports.
// A pid alone proves nothing: once its process ends, the system gives the
// number to the next program that starts. So each child is remembered with
// when it started, and a later start signals only a process that has both the
// pid and that start: one of ours, never a stranger that inherited the number.
import { type ChildProcess, spawnSync } from "node:child_process";
import { existsSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { startTimeOf } from "../core/processes/start-time";

const FILE = "launcher-children.json";

interface Child {
  pid: number;
  started: string;
}

/**
 * When the process now holding `pid` started, or null if none does. Linux says so exactly (in clock
 * ticks, of this boot); elsewhere `ps` gives the start to the second, with the command line.
 */
export function startOf(pid: number): string | null {
  if (process.platform === "linux") {
    try {
      const boot = readFileSync("/proc/sys/kernel/random/boot_id", "utf8").trim();
      const started = startTimeOf(readFileSync(`/proc/${pid}/stat`, "utf8"));
      return started && `${boot}/${started}`;
    } catch {
      return null;
    }
  }
  const ps = spawnSync("ps", ["-o", "lstart=", "-o", "command=", "-p", String(pid)], { encoding: "utf8" });
  return ps.status === 0 && ps.stdout.trim() ? ps.stdout.trim() : null;
}

export function rememberChildren(dataDir: string, pids: number[]) {
  const children = pids.flatMap((pid): Child[] => {
    const started = startOf(pid);
    return started ? [{ pid, started }] : [];
  });
  writeFileSync(join(dataDir, FILE), JSON.stringify(children));
}

/** After a clean stop: nothing is left to stop, and the pids will soon be other programs'. */
export function forgetChildren(dataDir: string) {
  rmSync(join(dataDir, FILE), { force: true });
}

/**
 * Stops what an earlier launcher left running, and forgets the list: `stopped` were its children,
 * `leftAlone` are pids it named that other programs hold now (or a list of bare pids, written before
 * start times were kept, that proves nothing).
 */
export function stopOrphanedChildren(dataDir: string): { stopped: number[]; leftAlone: number[] } {
  const file = join(dataDir, FILE);
  const stopped: number[] = [];
  const leftAlone: number[] = [];
  if (!existsSync(file)) return { stopped, leftAlone };
  let listed: unknown;
  try {
    listed = JSON.parse(readFileSync(file, "utf8"));
  } catch {
    listed = [];
  }
  for (const entry of Array.isArray(listed) ? listed : []) {
    const child = entry as Partial<Child>;
    const pid = typeof entry === "number" ? entry : child.pid;
    if (typeof pid !== "number" || !Number.isInteger(pid) || pid <= 0) continue;
    const now = startOf(pid);
    if (!now) continue; // gone
    if (now !== child.started) {
      leftAlone.push(pid);
      continue;
    }
    try {
      process.kill(pid, "SIGTERM");
      stopped.push(pid);
    } catch {
      // Ended between the look and the signal.
    }
  }
  forgetChildren(dataDir);
  return { stopped, leftAlone };
}

/** Asks a child to stop and resolves once it has; one that ignores it for 10 s is killed. */
export function stopChild(child: ChildProcess): Promise<void> {
  if (child.exitCode !== null || child.signalCode !== null) return Promise.resolve();
  return new Promise((done) => {
    const kill = setTimeout(() => child.kill("SIGKILL"), 10_000);
    child.once("exit", () => {
      clearTimeout(kill);
      done();
    });
    child.kill("SIGTERM");
  });
}
