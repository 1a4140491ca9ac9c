// bench/trial-latency: wizard message in → robot message received by the
// simulated robot, and → every observer updated, for 1 trial and for 50
// concurrent trials with 10 observers each (their pages showing the robot's
// camera, and not: in an order drawn each run), and 20 wizards back to back; and
// one trial followed by 50 observers, each observer's latency its own.
// Everything real: PostgreSQL, the runtime process as the launcher runs it,
// the NAO6 plugin, roslib and the simulator (see support-live.ts).
// Takes about 45 s.
import { cpuWhile } from "./support-cpu";
import { percentile, report } from "./support";
import { startLiveBench } from "./support-live";

/** With many trials, each wizard sends at most one command per PACE_MS: ten a second, far above a person's pace. */
const PACE_MS = 100;
const p99Of = (samples: number[]) =>
  percentile(
    [...samples].sort((a, b) => a - b),
    99,
  );

const live = await startLiveBench();
const { runTrial, quiet } = live;

const single = { robot: [] as number[], observers: [] as number[] };
await runTrial(30, [], []); // warm-up
// Each phase begins with every robot quiet (see `quiet`).
await quiet();
const cpu = <T>(work: () => Promise<T>) => cpuWhile(live.runtimePid, work);
const [, singleCpu] = await cpu(() => runTrial(1000, single.robot, single.observers));
report("1 trial: wizard message → robot received", single.robot, 5);
report("1 trial: wizard message → 10 observers updated", single.observers, 5);
console.log(singleCpu);

// One trial followed by many: each observer's own latency, not only the last's.
const CROWD = 50;
const crowd = { robot: [] as number[], observers: [] as number[] };
const each = Array.from({ length: CROWD }, () => [] as number[]);
await quiet();
const [, crowdCpu] = await cpu(() => runTrial(1000, crowd.robot, crowd.observers, { observing: CROWD, toEach: each }));
const worst = each.reduce((w, samples) => (p99Of(samples) > p99Of(w) ? samples : w));
report(`1 trial × ${CROWD} observers: → the slowest observer (by p99)`, worst, 5);
report(`1 trial × ${CROWD} observers: → all ${CROWD} observers updated`, crowd.observers);
// One line reaches the bench's pages one after another (the runtime's writes, then this one process's reads
// in turn): the first page's figure and the spread to the last tell the two apart from the path itself.
const byLine = each[0]!.map((_, i) => each.map((samples) => samples[i]!));
report(
  `1 trial × ${CROWD} observers: → the first observer of each line`,
  byLine.map((line) => Math.min(...line)),
);
report(
  `1 trial × ${CROWD} observers: first to last observer of each line`,
  byLine.map((line) => Math.max(...line) - Math.min(...line)),
);
console.log(crowdCpu);

// 50 trials × 10 observers at a wizard's pace, twice: every page showing the robot's camera (held to the
// target), and the observers' pages not showing it (hidden tabs, the panel closed: 500 of the 550 pages get no
// pictures; no target), so the camera's share (five pictures a second to each page that shows it) is printed.
// Which runs first is drawn each run: the second runs on the first's aftermath, so over runs neither is favoured.
/** One paced phase of 50 trials; its figures and the CPU's share. */
async function paced(cameraHidden: boolean) {
  const figures = { robot: [] as number[], observers: [] as number[], started: [] as number[] };
  await quiet();
  const fifty = live.group(50, PACE_MS, figures.started);
  const [, shares] = await cpu(() =>
    Promise.all(
      Array.from({ length: 50 }, () =>
        runTrial(40, figures.robot, figures.observers, { paceMs: PACE_MS, together: fifty, cameraHidden }),
      ),
    ),
  );
  return { ...figures, shares };
}
await live.robotsUpTo(51);
const hiddenFirst = Math.random() < 0.5;
const first = await paced(hiddenFirst);
const second = await paced(!hiddenFirst);
const [many, hidden] = hiddenFirst ? [second, first] : [first, second];
const order = (ranFirst: boolean) => (ranFirst ? "ran first" : "ran second");
report("50 trials × 10 observers, started at once: start → acknowledged", many.started);
report(`50 trials × 10 observers, 1 msg/${PACE_MS} ms each: → robot received`, many.robot, 25);
report(`50 trials × 10 observers, 1 msg/${PACE_MS} ms each: → all observers updated`, many.observers, 25);
console.log(`${many.shares} (${order(!hiddenFirst)})`);
report(`same, the observers' camera hidden: → robot received`, hidden.robot);
report(`same, the observers' camera hidden: → all observers updated`, hidden.observers);
console.log(`${hidden.shares} (${order(hiddenFirst)})`);

const flood = { robot: [] as number[], observers: [] as number[] };
await quiet();
const [, floodCpu] = await cpu(() =>
  Promise.all(Array.from({ length: 50 }, () => runTrial(20, flood.robot, flood.observers))),
);
report("50 trials × 10 observers, back to back (saturation): → robot", flood.robot);
report("50 trials × 10 observers, back to back (saturation): → observers", flood.observers);
console.log(floodCpu);

// Many wizards at once, each sending its next line as soon as the robot has the last: what one runtime
// and one database carry. Each action is three events (requested, dispatched, completed): the request is
// committed before the robot is told; its outcomes share a commit when they come together.
const WIZARDS = 20;
const wizards = { robot: [] as number[] };
await quiet();
// Timed inside, so that reading the CPU counters is not in the throughput.
const [[wizardTrials, seconds], wizardsCpu] = await cpu(async () => {
  const began = performance.now();
  const ids = await Promise.all(
    Array.from({ length: WIZARDS }, () => runTrial(150, wizards.robot, [], { observing: 0 })),
  );
  return [ids, (performance.now() - began) / 1000] as const;
});
report(`${WIZARDS} wizards back to back: wizard message → robot`, wizards.robot, 25);
const perSecond = wizards.robot.length / seconds;
console.log(
  `${`${WIZARDS} wizards back to back: throughput`.padEnd(58)} n=${String(wizards.robot.length).padStart(6)}  ${perSecond.toFixed(0)} actions/s  target ≥ 1500: ${perSecond >= 1500 ? "met" : "NOT met"} (ratio ${(perSecond / 1500).toFixed(2)})`,
);

console.log(wizardsCpu);

const commits = await live.commits(wizardTrials);
console.log(
  `${`${WIZARDS} wizards back to back: commits`.padEnd(58)} ${(commits.perTrial / commits.actions).toFixed(2)} per action in its trial, ${commits.overall} transactions for ${commits.actions} actions of ${WIZARDS} trials`,
);
console.log(`refused commands: ${live.refused()}`);
await live.stop();
process.exit(0);
