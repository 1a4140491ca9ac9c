// Runs the core's long work (../core/work.ts) a few milliseconds at a time,
// handing the event loop back in between: a large design imported or
// published by one researcher does not hold up anyone else's request, nor
// does a trial of it opening in the runtime hold up the other trials.
import type { Work } from "@/core/work";

/** Long enough that the hand-backs cost little, short enough that no one waiting notices. */
const SLICE_MS = 4;

export async function sliced<T>(work: Work<T>): Promise<T> {
  let began = performance.now();
  for (;;) {
    const next = work.next();
    if (next.done) return next.value;
    if (performance.now() - began >= SLICE_MS) {
      await new Promise((resume) => setImmediate(resume));
      began = performance.now();
    }
  }
}
