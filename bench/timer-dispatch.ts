// bench/timer-dispatch: a step's time limit running out → the next action at
// the robot. One trial loops: "Wait" (no actions, a 50 ms limit leading to
// "Say") and "Say" (one line, then back to "Wait"). The bench's wizard
// presses Next the moment the trial enters "Say" by the time limit, as the
// wizard's page would at once; its line then goes to the simulated robot.
// Lateness: the robot's receipt minus the timer's due time (its logged start
// plus its limit, on the runtime's clock), so it counts the runtime's own
// timer, the fire's commit, the wizard told, the request's commit and the
// dispatch. Everything real (see support-live.ts). Takes about 30 s after
// the database has started. Its three parts are printed too, without a
// target, to show where a slow one lost its time: the fire as logged (whole
// milliseconds of the runtime's clock), the wizard told of it (the bench's
// clock; one machine, one wall clock), and the wizard's Next to the robot.
import type { ProtocolSnapshot } from "../src/core/protocol/document";
import { eventsSince } from "../src/store/event-store";
import { report } from "./support";
import { sayStep, startLiveBench } from "./support-live";

const FIRES = 300;
const WARM_UP = 20;
const LINE = "Time is up.";
const steps: ProtocolSnapshot["steps"] = [
  {
    id: "wait",
    name: "Wait",
    description: "",
    actions: [],
    timeLimit: { seconds: 0.05, after: { to: "step", stepId: "say" } },
  },
  sayStep(LINE),
];

// The robot says its line at once: the speaking would set the pace, not what is measured.
const live = await startLiveBench({ steps, msPerChar: 0 });
const trial = await live.newTrial();
const told: number[] = [];
const { receipts, seconds, refusedPresses } = await live.loop(trial.id, {
  line: LINE,
  via: "timeout",
  count: FIRES + WARM_UP,
  onPress: (at) => told.push(at),
});

const log = await eventsSince(live.db, trial.id);
const t0 = log.find((e) => e.type === "trial.started")!.serverTime.getTime();
const due = log
  .filter((e) => e.type === "timer.started")
  .map((e) => {
    const { seconds } = e as unknown as { seconds: number };
    return t0 + e.relMs! + seconds * 1000;
  });
// The k-th line follows the k-th time limit; the first few warm the runtime and the socket.
// Receipts on the wall clock, as the runtime's due times are.
const wall = (at: number) => performance.timeOrigin + at;
const lateness = receipts.slice(WARM_UP).map((at, k) => wall(at) - due[WARM_UP + k]!);
const fired = log
  .filter((e) => e.type === "step.entered" && "via" in e && e.via === "timeout")
  .map((e) => t0 + e.relMs!);
const counted = (parts: (k: number) => number) => Array.from({ length: FIRES }, (_, i) => parts(WARM_UP + i));
report("time limit due → next action received by the robot", lateness, 10);
report(
  "  of which: due → the fire logged (whole ms)",
  counted((k) => fired[k]! - due[k]!),
);
report(
  "  of which: the fire logged → the wizard told",
  counted((k) => wall(told[k]!) - fired[k]!),
);
report(
  "  of which: the wizard's Next → received by the robot",
  counted((k) => receipts[k]! - told[k]!),
);
console.log(`${"duration of the fires".padEnd(58)} ${seconds.toFixed(1)} s`);
if (refusedPresses) console.error(`refused Next presses: ${refusedPresses}`);
await live.stop();
process.exit(0);
