// A restart stops the children an earlier launcher left, and only them: a pid
// it remembered that another program holds now is left alone.
import { type ChildProcess, spawn } from "node:child_process";
import { existsSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterEach, describe, expect, it } from "vitest";
import { scratchFolder } from "../../tests/support/scratch";
import { forgetChildren, rememberChildren, stopOrphanedChildren } from "./children";

const running: ChildProcess[] = [];
afterEach(() => {
  for (const p of running.splice(0)) p.kill("SIGKILL");
});

/** A `sleep 60`, and the signal it will end by. */
function sleeper() {
  const child = spawn("sleep", ["60"], { stdio: "ignore" });
  running.push(child);
  const ended = new Promise<NodeJS.Signals | null>((ok) => child.once("exit", (_code, signal) => ok(signal)));
  return { pid: child.pid!, ended, kill: (signal: NodeJS.Signals) => child.kill(signal) };
}
/** Whether it was still running, untouched: the signal that ends it is the one sent now. */
async function survived(child: ReturnType<typeof sleeper>) {
  child.kill("SIGKILL");
  return (await child.ended) === "SIGKILL";
}

const folder = () => scratchFolder("children-");
const file = (dir: string) => join(dir, "launcher-children.json");

describe("the children an earlier start left", () => {
  it("stops a child of its own, and leaves alone a stranger given a pid it remembered", async () => {
    const dir = folder();
    const ours = sleeper();
    const stranger = sleeper();
    const strangerWithBareRecord = sleeper();
    rememberChildren(dir, [ours.pid]);
    const [record] = JSON.parse(readFileSync(file(dir), "utf8"));
    // As after a reboot or a long stop: pids named, their processes long gone, the numbers given to others.
    const planted = [
      { pid: stranger.pid, started: "the start of an earlier process" },
      strangerWithBareRecord.pid, // the list as launchers wrote it before start times were kept
      record,
    ];
    writeFileSync(file(dir), JSON.stringify(planted));

    const result = stopOrphanedChildren(dir);

    expect(result).toEqual({ stopped: [ours.pid], leftAlone: [stranger.pid, strangerWithBareRecord.pid] });
    expect(await ours.ended).toBe("SIGTERM");
    expect(await survived(stranger)).toBe(true);
    expect(await survived(strangerWithBareRecord)).toBe(true);
    expect(existsSync(file(dir))).toBe(false);
  });

  it("signals nothing for children that have ended, and forgets them", async () => {
    const dir = folder();
    const gone = sleeper();
    rememberChildren(dir, [gone.pid]);
    gone.kill("SIGKILL");
    await gone.ended;
    expect(stopOrphanedChildren(dir)).toEqual({ stopped: [], leftAlone: [] });
    expect(existsSync(file(dir))).toBe(false);
  });

  it("forgets its children on a clean stop", () => {
    const dir = folder();
    rememberChildren(dir, [sleeper().pid]);
    forgetChildren(dir);
    expect(existsSync(file(dir))).toBe(false);
    expect(stopOrphanedChildren(dir)).toEqual({ stopped: [], leftAlone: [] });
  });
});
