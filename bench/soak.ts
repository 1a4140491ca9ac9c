// bench/soak: 50 trials × 10 observers at a wizard's pace for SOAK_MINUTES
// (10 by default), then 20 wizards back to back; the runtime's resident
// memory sampled every 2 s throughout. Targets: no command refused, and memory
// that stays flat while the trials run. Resident memory saws up and down with
// the garbage collector (by 50 % over a cycle of a minute or two), so each
// two minutes are judged by their floor, the lowest sample, which is what the
// runtime still holds after a collection; the growth is from the second
// window's floor (all 50 trials open, their sockets, robot links and buffers
// held) to the last whole window's. From the idle runtime before any trial opened it would
// count holding 50 trials as growth: that figure is printed too.
// Takes SOAK_MINUTES and about a minute more.
import { report } from "./support";
import { startLiveBench } from "./support-live";

const MINUTES = Number(process.env.SOAK_MINUTES ?? 10);
/** A wizard's pace: a line every two seconds. */
const PACE_MS = 2000;

const live = await startLiveBench();
// A robot for each of the 50 trials, and one for the trial before them still letting go.
await live.robotsUpTo(51);
await live.runTrial(30, [], []); // warm-up
const idle = live.runtimeMemoryMiB();
const began = performance.now();
const memory: Array<{ s: number; mib: number }> = [];
const sample = () => memory.push({ s: Math.round((performance.now() - began) / 1000), mib: live.runtimeMemoryMiB() });
const sampler = setInterval(sample, 2_000);

const lines = Math.floor((MINUTES * 60_000) / PACE_MS);
const paced = { robot: [] as number[], observers: [] as number[], started: [] as number[] };
// Side by side once all have started, each wizard beginning at its own moment (see runTrial's `together`).
const fifty = live.group(50, PACE_MS, paced.started);
await Promise.all(
  Array.from({ length: 50 }, () =>
    live.runTrial(lines, paced.robot, paced.observers, { paceMs: PACE_MS, together: fifty }),
  ),
);
report("soak: 50 trials × 10 observers, started at once: start → acknowledged", paced.started);
const running = (performance.now() - began) / 1000;
report(`soak: 50 trials × 10 observers, ${MINUTES} min: → robot`, paced.robot, 25);
report(`soak: 50 trials × 10 observers, ${MINUTES} min: → all observers`, paced.observers, 25);

const burst = { robot: [] as number[] };
await Promise.all(Array.from({ length: 20 }, () => live.runTrial(150, burst.robot, [], { observing: 0 })));
report("soak: then 20 wizards back to back: → robot", burst.robot, 25);

sample();
clearInterval(sampler);
const WINDOW_S = 120;
/** The lowest sample of each whole window while the 50 trials ran. */
const floors = Array.from({ length: Math.floor(running / WINDOW_S) }, (_, w) =>
  Math.min(...memory.filter((m) => m.s >= w * WINDOW_S && m.s < (w + 1) * WINDOW_S).map((m) => m.mib)),
);
console.log(`soak: runtime memory floor of each 2 minutes (MiB): ${floors.map((f) => f.toFixed(0)).join(" ")}`);
if (floors.length < 3) {
  // Growth is judged from the second window to the last: a shorter run has nothing to compare.
  console.log(`soak: runtime memory growth needs SOAK_MINUTES of 6 or more to be judged (this run: ${MINUTES})`);
} else {
  const [steady, last] = [floors[1]!, floors.at(-1)!];
  const growth = (last - steady) / steady;
  console.log(
    `soak: runtime memory with 50 trials running: floor of minutes 2–4 ${steady.toFixed(1)} MiB, of the last two ${last.toFixed(1)} MiB; growth ${(growth * 100).toFixed(1)} %  target < 10 %: ${growth < 0.1 ? "met" : "NOT met"} (ratio ${(growth / 0.1).toFixed(2)})`,
  );
}
console.log(
  `soak: runtime memory idle before the trials ${idle.toFixed(1)} MiB, most ${Math.max(...memory.map((m) => m.mib)).toFixed(1)} MiB, after the back-to-back wizards ${memory.at(-1)!.mib.toFixed(1)} MiB`,
);
const refused = live.refused();
console.log(`soak: commands refused: ${refused}  target 0: ${refused === 0 ? "met" : "NOT met"}`);
await live.stop();
process.exit(0);
