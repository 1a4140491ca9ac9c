// How often each loop of the protocol went round in one trial, read from its
// log: each time back is a step.entered of the loop, its bound a
// loop.bound_reached. The fidelity report carries it; the analysis shows it.
import { loopsOf, type TrialEvent, type TrialProtocol } from "@/core/trial";

export interface LoopCount {
  /** The loop's name in the log (src/core/trial/loops.ts). */
  loop: string;
  /** The step it leaves from, and the step it goes back to. */
  stepId: string;
  backToStepId: string;
  /** Its bound: at most this many times back. */
  times: number;
  /** How many times it went back in this trial. */
  taken: number;
  /** Whether it went back its `times` and the trial then took its way on. */
  boundReached: boolean;
}

export function loopCounts(protocol: TrialProtocol, events: readonly TrialEvent[]): LoopCount[] {
  const taken = new Map<string, number>();
  const reached = new Set<string>();
  for (const e of events) {
    if (e.type === "step.entered" && e.via === "loop" && e.loop) taken.set(e.loop, (taken.get(e.loop) ?? 0) + 1);
    if (e.type === "loop.bound_reached") reached.add(e.loop);
  }
  return loopsOf(protocol).map(({ name, stepId, loop }) => ({
    loop: name,
    stepId,
    backToStepId: loop.stepId,
    times: loop.times,
    taken: taken.get(name) ?? 0,
    boundReached: reached.has(name),
  }));
}
