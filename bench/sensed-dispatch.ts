// bench/sensed-dispatch: an event the robot senses → the next action at the
// robot. One trial loops: "Wait" (a Wait for 'ready' heard, leading to "Say")
// and "Say" (one line, then back to "Wait"). The bench fires the event as the
// simulated robot's Robot page does (a stimulus over rosbridge, roslib), the
// moment the trial enters "Wait"; the simulator publishes the recognised
// word on /word_recognized as it takes the stimulus. The bench's wizard
// presses Next the moment the trial enters "Say" by the event, as the
// wizard's page would at once; its line then goes to the simulated robot.
// Lateness: the line's receipt at the robot minus the stimulus's (the word
// published), both on this process's clock, so it counts the runtime's
// watcher, the sensed event's commit, the wizard told, the request's commit
// and the dispatch. A phrase rather than a touch: a touch is released 300 ms
// later and the next cannot come before. Everything real (see
// support-live.ts). Takes about 30 s after the database has started.
import * as ROSLIB from "roslib";
import type { ProtocolSnapshot } from "../src/core/protocol/document";
import { type Stimulus, STIMULUS_TOPIC } from "../src/core/robots/stimulus";
import { report } from "./support";
import { sayStep, startLiveBench } from "./support-live";

const EVENTS = 300;
const WARM_UP = 20;
const LINE = "I heard you.";
const READY: Stimulus = { event: "heard_ready", heard: "ready", confidence: 0.9 };
const steps: ProtocolSnapshot["steps"] = [
  {
    id: "wait",
    name: "Wait",
    description: "",
    actions: [
      {
        id: "ready",
        type: "wait_for",
        name: "",
        parameters: { events: [{ id: "heard", event: "heard_ready", after: { to: "step", stepId: "say" } }] },
        parallelGroup: null,
      },
    ],
  },
  sayStep(LINE),
];

// The robot says its line at once: the speaking would set the pace, not what is measured.
const live = await startLiveBench({ steps, msPerChar: 0 });
const trial = await live.newTrial(0);
const sim = live.sims[0]!;

// The Robot page: a roslib client on the simulated robot, one publisher of stimuli.
const page = new ROSLIB.Ros({ url: sim.url });
await new Promise<void>((ok, fail) => {
  page.on("connection", () => ok());
  page.on("error", (e) => fail(new Error(`Could not reach the simulated robot at ${sim.url}: ${String(e)}`)));
});
const control = new ROSLIB.Topic({ ros: page, name: STIMULUS_TOPIC, messageType: "std_msgs/msg/String" });
const fire = () => control.publish({ data: JSON.stringify(READY) });

/** When each stimulus reached the robot (performance.now()). */
const fired: number[] = [];
live.heard.set(JSON.stringify(READY), (at) => fired.push(at));
const { receipts, seconds, refusedPresses } = await live.loop(trial.id, {
  line: LINE,
  via: "sensed",
  count: EVENTS + WARM_UP,
  // The wait pending: the participant says "ready" (the first after the start too).
  onWait: fire,
  // The trial's robot link watches /word_recognized from the wizard's hello on: before that a word is lost.
  beforeStart: async () => {
    while (
      !sim.received.some((r) => {
        const m = r.message as { op?: string; topic?: string };
        return m.op === "subscribe" && m.topic === "/word_recognized";
      })
    )
      await new Promise((r) => setTimeout(r, 20));
  },
});
page.close();

// The k-th line follows the k-th word; the first few warm the runtime and the socket.
const lateness = receipts.slice(WARM_UP).map((at, k) => at - fired[WARM_UP + k]!);
report("robot event published → next action received by the robot", lateness, 10);
console.log(`${"duration of the events".padEnd(58)} ${seconds.toFixed(1)} s`);
if (refusedPresses) console.error(`refused Next presses: ${refusedPresses}`);
await live.stop();
process.exit(0);
