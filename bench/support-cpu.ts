// Where the machine's cores went while a figure was measured: the runtime the
// bench started, PostgreSQL, the bench process itself (which stands in for
// the browsers and robots of a lab, on machines of their own there) and the
// rest. On a machine of two cores the three share them, and a tail that is
// the machine's, not the path's, shows here. Read from /proc: Linux only
// (elsewhere nothing is printed).
import { existsSync, readdirSync, readFileSync } from "node:fs";
import { availableParallelism } from "node:os";

type Part = "runtime" | "database" | "bench" | "other";

/** Clock ticks of CPU (user and system) each part has used so far. */
function ticks(runtimePid: number): Record<Part, number> {
  const used: Record<Part, number> = { runtime: 0, database: 0, bench: 0, other: 0 };
  for (const pid of readdirSync("/proc").filter((name) => /^\d+$/.test(name))) {
    try {
      const stat = readFileSync(`/proc/${pid}/stat`, "utf8");
      // The command name may hold spaces and parentheses: the fields are counted after its closing one.
      const fields = stat.slice(stat.lastIndexOf(")") + 2).split(" ");
      const part: Part =
        Number(pid) === process.pid
          ? "bench"
          : Number(pid) === runtimePid
            ? "runtime"
            : readFileSync(`/proc/${pid}/cmdline`, "utf8").includes("postgres")
              ? "database"
              : "other";
      used[part] += Number(fields[11]) + Number(fields[12]);
    } catch {
      // A process that ended between the listing and the read.
    }
  }
  return used;
}

/** Runs `work`: what it gives, and each part's share of one core meanwhile as a line ("" where there is no /proc). */
export async function cpuWhile<T>(runtimePid: number, work: () => Promise<T>): Promise<[T, string]> {
  if (!existsSync("/proc/self/stat")) return [await work(), ""];
  const began = { at: performance.now(), used: ticks(runtimePid) };
  const result = await work();
  const seconds = (performance.now() - began.at) / 1000;
  const used = ticks(runtimePid);
  // Linux counts CPU time in ticks of 1/100 s (USER_HZ).
  const share = (part: Part) => `${part} ${Math.round((used[part] - began.used[part]) / seconds)}%`;
  const parts = (["runtime", "database", "bench", "other"] as const).map(share).join(", ");
  return [result, `${"  cpu while measured (% of one core)".padEnd(58)} ${parts}; ${availableParallelism()} cores`];
}
