// bench/timer-dispatch: a step's time limit running out → the next action at
// the robot. One trial loops: "Wait" (no actions, a 50 ms limit leading to
// "Say") and "Say" (one line, then back to "Wait"). The bench's wizard
// presses Next the moment the trial enters "Say" by the time limit, as the
// wizard's page would at once; its line then goes to the simulated robot.
// Lateness: the robot's receipt minus the timer's due time (its logged start
// plus its limit, on the runtime's clock), so it counts the runtime's own
// timer, the fire's commit, the wizard told, the request's commit and the
// dispatch. Everything real (see support-live.ts). Takes about 30 s after
// the database has started.
import type { ProtocolSnapshot } from "../src/core/protocol/document";
import { eventsSince } from "../src/store/event-store";
import { report } from "./support";
import { startLiveBench } from "./support-live";

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
  {
    id: "say",
    name: "Say",
    description: "",
    after: { to: "step", stepId: "wait" },
    actions: [{ id: "line", type: "say", name: "", parameters: { text: LINE }, parallelGroup: null }],
  },
];

// The robot says its line at once: the speaking would set the pace, not what is measured.
const live = await startLiveBench({ steps, msPerChar: 0 });
const trial = await live.newTrial();
/** When each line reached the robot, on the wall clock (the runtime's due times are on it too). */
const receipts: number[] = [];
let done: () => void;
const finished = new Promise<void>((ok) => (done = ok));
live.heard.set(LINE, (at) => {
  receipts.push(performance.timeOrigin + at);
  if (receipts.length === FIRES + WARM_UP) done();
});
let fails = 0;
const wizard = await live.socket(trial.id, live.wizardId, (events) => {
  for (const e of events as Array<{ type: string; stepId?: string; via?: string; actionId?: string }>) {
    // Next at once: on "Say" entered by the time limit (its line), and once the line is said (back to "Wait").
    const press =
      (e.type === "step.entered" && e.stepId === "say" && e.via === "timeout") ||
      (e.type === "action.completed" && e.actionId === "line");
    if (press) void wizard.command({ kind: "next" }).then((refusal) => refusal && fails++);
  }
});
const began = performance.now();
const refused = await wizard.command({ kind: "start" });
if (refused) throw new Error(`The runtime refused to start the trial: ${refused}`);
await finished;
await wizard.command({ kind: "complete" });
wizard.close();

const log = await eventsSince(live.db, trial.id);
const t0 = log.find((e) => e.type === "trial.started")!.serverTime.getTime();
const due = log
  .filter((e) => e.type === "timer.started")
  .map((e) => {
    const { seconds } = e as unknown as { seconds: number };
    return t0 + e.relMs! + seconds * 1000;
  });
// The k-th line follows the k-th time limit; the first few warm the runtime and the socket.
const lateness = receipts.slice(WARM_UP).map((at, k) => at - due[WARM_UP + k]!);
report("time limit due → next action received by the robot", lateness, 10);
console.log(`${"duration of the fires".padEnd(58)} ${((performance.now() - began) / 1000).toFixed(1)} s`);
if (fails) console.error(`refused Next presses: ${fails}`);
await live.stop();
process.exit(0);
