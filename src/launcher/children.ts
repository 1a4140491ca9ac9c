// Child processes the launcher starts, remembered on disk so that a launcher
// killed with -9 does not leave the next start fighting its orphans for ports.
import { existsSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";

const FILE = "launcher-children.json";

export function rememberChildren(dataDir: string, pids: number[]) {
  writeFileSync(join(dataDir, FILE), JSON.stringify(pids));
}

export function stopOrphanedChildren(dataDir: string): number[] {
  const file = join(dataDir, FILE);
  if (!existsSync(file)) return [];
  const stopped: number[] = [];
  for (const pid of JSON.parse(readFileSync(file, "utf8")) as number[]) {
    try {
      process.kill(pid, "SIGTERM");
      stopped.push(pid);
    } catch {
      // Already gone.
    }
  }
  return stopped;
}
