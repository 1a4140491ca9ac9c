// A trial's time limits on the server's clock. Each timer the trial's state
// has running is armed to fire at its logged start plus its time limit, so a
// runtime that opens the trial again after a restart fires it when it was
// due (at once if that has passed). The log decides everything else: a timer
// fired or cancelled there is disarmed, and a fire the engine refuses (the
// wizard acted first) is nothing.
import { dueAt, type TrialState } from "@/core/trial";

export class TrialTimers {
  private readonly armed = new Map<string, ReturnType<typeof setTimeout>>();

  constructor(private readonly fire: (timerId: string) => void) {}

  /**
   * Arms what `timers` has running and is not armed yet; disarms what it no
   * longer has. `t0` is the trial's start on the server's clock. A fire refused
   * while the trial is paused is armed again by the next change (its resume).
   */
  follow(timers: TrialState["timers"], t0: number | null) {
    for (const [timerId, handle] of this.armed) {
      if (timerId in timers) continue;
      clearTimeout(handle);
      this.armed.delete(timerId);
    }
    if (t0 === null) return;
    for (const [timerId, timer] of Object.entries(timers)) {
      const due = dueAt(timer, t0);
      if (this.armed.has(timerId) || due === null) continue;
      const handle = setTimeout(
        () => {
          this.armed.delete(timerId);
          this.fire(timerId);
        },
        Math.max(0, due - Date.now()),
      );
      this.armed.set(timerId, handle);
    }
  }

  close() {
    for (const handle of this.armed.values()) clearTimeout(handle);
    this.armed.clear();
  }
}
