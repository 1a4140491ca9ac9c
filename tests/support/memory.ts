// What a piece of code holds in memory: the buffers still reachable after a
// full collection (so garbage not yet collected never counts).
import { setFlagsFromString } from "node:v8";
import { runInNewContext } from "node:vm";

setFlagsFromString("--expose-gc");
const collect = runInNewContext("gc") as () => void;

/** Bytes of buffers alive now. */
export function liveBuffers(): number {
  collect();
  return process.memoryUsage().arrayBuffers;
}

/** The most buffer memory `work` held beyond what was alive before it, sampled as often as the event loop allows. */
export async function heldDuring<T>(work: () => Promise<T>): Promise<{ result: T; held: number }> {
  const before = liveBuffers();
  let held = 0;
  const sample = setInterval(() => (held = Math.max(held, liveBuffers() - before)), 5);
  try {
    const result = await work();
    return { result, held };
  } finally {
    clearInterval(sample);
  }
}
