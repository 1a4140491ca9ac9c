// The runtime's time limits on the real clock: each fires once, never before
// it is due, and one disarmed (the wizard moved on, the trial paused) never
// fires, even in the last milliseconds it spends awake before its due time.
import { afterEach, describe, expect, it } from "vitest";
import type { RunningTimer, TrialState } from "@/core/trial";
import { TrialTimers } from "./trial-timers";

const stateWith = (timers: Record<string, RunningTimer>, status: TrialState["status"] = "in_progress") =>
  ({ status, timers }) as unknown as TrialState;
/** A step's limit of `seconds`, started at `startedMs` from t0. */
const limit = (seconds: number, startedMs = 0): RunningTimer => ({ stepId: "s", seconds, startedMs, pausedMs: 0 });
const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));
/** Waits for `done`, however slowly a loaded machine runs the timers (at most 5 s). */
const until = async (done: () => boolean) => {
  for (let i = 0; i < 250 && !done(); i++) await sleep(20);
};

describe("a trial's time limits", () => {
  const made: TrialTimers[] = [];
  const timers = (fire: (timerId: string) => void) => {
    const t = new TrialTimers(fire);
    made.push(t);
    return t;
  };
  afterEach(() => {
    for (const t of made.splice(0)) t.close();
  });

  it("fires each limit once, never before its due time", async () => {
    const fired: Array<{ timerId: string; at: number }> = [];
    const t = timers((timerId) => fired.push({ timerId, at: Date.now() }));
    const t0 = Date.now();
    const state = stateWith({ a: limit(0.03), b: limit(0.06) });
    t.follow(state, t0);
    // Following the same state again arms nothing twice.
    t.follow(state, t0);
    await until(() => fired.length >= 2);
    await sleep(20);
    expect(fired.map((f) => f.timerId)).toEqual(["a", "b"]);
    expect(fired[0]!.at).toBeGreaterThanOrEqual(t0 + 30);
    expect(fired[1]!.at).toBeGreaterThanOrEqual(t0 + 60);
  });

  it("fires each of 200 limits of 50 trials once, never before its due time, as a runtime running 50 trials has them", async () => {
    const fired = new Map<string, number[]>();
    const t0 = Date.now();
    const due = new Map<string, number>();
    for (let trial = 0; trial < 50; trial++) {
      const limits: Record<string, RunningTimer> = {};
      for (let k = 0; k < 4; k++) {
        // Due times spread over 20-119 ms, several on the same millisecond.
        const ms = 20 + ((trial * 7 + k * 31) % 100);
        limits[`limit ${k}`] = limit(ms / 1000);
        due.set(`${trial}/limit ${k}`, t0 + ms);
      }
      const t = timers((timerId) => {
        const id = `${trial}/${timerId}`;
        fired.set(id, [...(fired.get(id) ?? []), Date.now()]);
      });
      t.follow(stateWith(limits), t0);
    }
    await until(() => fired.size === 200);
    await sleep(20);
    expect(fired.size).toBe(200);
    for (const [id, at] of fired) {
      expect(at, id).toHaveLength(1);
      expect(at[0], id).toBeGreaterThanOrEqual(due.get(id)!);
    }
  });

  it("fires at once a limit already past (a runtime that opened the trial again after its due time)", async () => {
    const fired: string[] = [];
    const t = timers((timerId) => fired.push(timerId));
    t.follow(stateWith({ late: limit(1, 0) }), Date.now() - 5000);
    await until(() => fired.length > 0);
    expect(fired).toEqual(["late"]);
  });

  it("never fires a limit disarmed in its last milliseconds awake before its due time", async () => {
    // A machine too busy to reach the last milliseconds before the due time has nothing to judge: tried again.
    for (let attempt = 0; attempt < 20; attempt++) {
      const fired: string[] = [];
      const t = timers((timerId) => fired.push(timerId));
      const t0 = Date.now();
      t.follow(stateWith({ a: limit(0.05) }), t0);
      // Awake and waiting by now (it wakes a few milliseconds early).
      while (Date.now() < t0 + 48) await new Promise((r) => setImmediate(r));
      const beforeDue = Date.now() < t0 + 50;
      t.follow(stateWith({}), t0);
      if (!beforeDue) continue;
      await sleep(60);
      expect(fired).toEqual([]);
      return;
    }
    throw new Error("This machine never reached the last milliseconds before a limit's due time in 20 tries.");
  });

  it("disarms everything while the trial is paused, and arms it again as it resumes", async () => {
    const fired: string[] = [];
    const t = timers((timerId) => fired.push(timerId));
    const t0 = Date.now();
    t.follow(stateWith({ a: limit(0.03) }), t0);
    t.follow(stateWith({ a: limit(0.03) }, "paused"), t0);
    await sleep(60);
    expect(fired).toEqual([]);
    t.follow(stateWith({ a: limit(0.03) }), t0);
    await until(() => fired.length > 0);
    expect(fired).toEqual(["a"]);
  });
});
