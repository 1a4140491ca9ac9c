// A trial's time limits on the server's clock. Each timer the trial's state
// has running is armed to fire at its logged start plus its time limit plus
// the time the trial was paused since, so a runtime that opens the trial
// again after a restart fires it when it was due (at once if that has
// passed). A paused trial's clocks stand still: nothing is armed until it
// resumes. The log decides everything else: a timer fired or cancelled there
// is disarmed, and a fire the engine refuses (the wizard acted first) is
// nothing.
import { dueMs, type TrialState } from "@/core/trial";

/**
 * How long before a limit is due its timer wakes, to wait out the rest on the
 * event loop. A process that has slept since the limit began wakes late on
 * this machine, now and then by several milliseconds (bench/timer-dispatch:
 * due → fire p99 5 ms, max 17, with the runtime's event loop idle throughout);
 * one awake fires on the due millisecond. The wait costs at most this much
 * processor time per limit.
 */
const WAKE_EARLY_MS = 4;

export class TrialTimers {
  /** Each armed timer's disarm: asleep or awake and waiting, it then never fires. */
  private readonly armed = new Map<string, () => void>();

  constructor(private readonly fire: (timerId: string) => void) {}

  /**
   * Arms what `state` has running and is not armed yet; disarms what it no
   * longer has, and everything while the trial is paused (its resume arms
   * them again with what they had left). `t0` is the trial's start on the
   * server's clock.
   */
  follow(state: TrialState, t0: number | null) {
    const paused = state.status === "paused";
    for (const [timerId, disarm] of this.armed) {
      if (timerId in state.timers && !paused) continue;
      disarm();
      this.armed.delete(timerId);
    }
    if (t0 === null || paused) return;
    for (const [timerId, timer] of Object.entries(state.timers)) {
      const due = dueMs(timer);
      if (this.armed.has(timerId) || due === null) continue;
      this.arm(timerId, t0 + due);
    }
  }

  close() {
    for (const disarm of this.armed.values()) disarm();
    this.armed.clear();
  }

  /** Sleeps until just before `at`, then waits on the event loop (other work goes between) until it is here. */
  private arm(timerId: string, at: number) {
    let armed = true;
    const onTime = () => {
      if (!armed) return;
      if (Date.now() < at) return void setImmediate(onTime);
      this.armed.delete(timerId);
      this.fire(timerId);
    };
    const sleeping = setTimeout(onTime, Math.max(0, at - WAKE_EARLY_MS - Date.now()));
    this.armed.set(timerId, () => {
      armed = false;
      clearTimeout(sleeping);
    });
  }
}
