// bench/soak: 50 trials × 10 observers at a wizard's pace for SOAK_MINUTES
// (10 by default), then 20 wizards back to back; the runtime's memory sampled
// throughout. Targets: memory at the end within 10 % of the start, and no
// command refused.
import { report } from "./support";
import { startLiveBench } from "./support-live";

const MINUTES = Number(process.env.SOAK_MINUTES ?? 10);
/** A wizard's pace: a line every two seconds. */
const PACE_MS = 2000;

const live = await startLiveBench();
await live.runTrial(30, [], []); // warm-up
const start = live.runtimeMemoryMiB();
const memory = [start];
const sampler = setInterval(() => memory.push(live.runtimeMemoryMiB()), 10_000);

const lines = Math.floor((MINUTES * 60_000) / PACE_MS);
const paced = { robot: [] as number[], observers: [] as number[] };
await Promise.all(Array.from({ length: 50 }, () => live.runTrial(lines, paced.robot, paced.observers, PACE_MS)));
report(`soak: 50 trials × 10 observers, ${MINUTES} min: → robot`, paced.robot, 25);
report(`soak: 50 trials × 10 observers, ${MINUTES} min: → all observers`, paced.observers, 25);

const burst = { robot: [] as number[] };
await Promise.all(Array.from({ length: 20 }, () => live.runTrial(150, burst.robot, [], 0, 0)));
report("soak: then 20 wizards back to back: → robot", burst.robot, 25);

clearInterval(sampler);
const end = live.runtimeMemoryMiB();
const growth = (end - start) / start;
console.log(
  `soak: runtime memory: start ${start.toFixed(1)} MiB, end ${end.toFixed(1)} MiB, most ${Math.max(...memory).toFixed(1)} MiB (${memory.length} samples); growth ${(growth * 100).toFixed(1)} %  target < 10 %: ${growth < 0.1 ? "met" : "NOT met"} (ratio ${(growth / 0.1).toFixed(2)})`,
);
const refused = live.refused();
console.log(`soak: commands refused: ${refused}  target 0: ${refused === 0 ? "met" : "NOT met"}`);
await live.stop();
process.exit(0);
