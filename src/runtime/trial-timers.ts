// A trial's time limits on the server's clock. Each timer the trial's state
// has running is armed to fire at its logged start plus its time limit plus
// the time the trial was paused since, so a runtime that opens the trial
// again after a restart fires it when it was due (at once if that has
// passed). A paused trial's clocks stand still: nothing is armed until it
// resumes. The log decides everything else: a timer fired or cancelled there
// is disarmed, and a fire the engine refuses (the wizard acted first) is
// nothing.
import { dueMs, type TrialState } from "@/core/trial";

export class TrialTimers {
  private readonly armed = new Map<string, ReturnType<typeof setTimeout>>();

  constructor(private readonly fire: (timerId: string) => void) {}

  /**
   * Arms what `state` has running and is not armed yet; disarms what it no
   * longer has, and everything while the trial is paused (its resume arms
   * them again with what they had left). `t0` is the trial's start on the
   * server's clock.
   */
  follow(state: TrialState, t0: number | null) {
    const paused = state.status === "paused";
    for (const [timerId, handle] of this.armed) {
      if (timerId in state.timers && !paused) continue;
      clearTimeout(handle);
      this.armed.delete(timerId);
    }
    if (t0 === null || paused) return;
    for (const [timerId, timer] of Object.entries(state.timers)) {
      const due = dueMs(timer);
      if (this.armed.has(timerId) || due === null) continue;
      const handle = setTimeout(
        () => {
          this.armed.delete(timerId);
          this.fire(timerId);
        },
        Math.max(0, t0 + due - Date.now()),
      );
      this.armed.set(timerId, handle);
    }
  }

  close() {
    for (const handle of this.armed.values()) clearTimeout(handle);
    this.armed.clear();
  }
}
