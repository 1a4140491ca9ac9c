// bench/robot-dispatch: 10,000 dispatches of the NAO6 plugin's say action
// through the real roslib client into the simulated robot over a loopback
// socket, timed from dispatch to the message arriving at the robot. The
// robot says each line at once (SIM_MS_PER_CHAR 0): a dispatch waits for the
// say to complete, and at the simulator's default 60 ms a character the
// speaking, not the dispatch, would set the pace (about 95 minutes).
// Takes about 10 s on a quiet machine.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { loadPlugin, type Plugin } from "../src/core/plugins";
import { startDefaultSimulator } from "../src/robots/simulator/main";
import { RosbridgeTransport } from "../src/robots/transports/rosbridge";
import { report } from "./support";

const DISPATCHES = 10_000;
const file = join(import.meta.dirname, "..", "plugins", "nao6-ros2.json");
const loaded = loadPlugin("nao6-ros2.json", readFileSync(file, "utf8"));
if (!loaded.ok) throw new Error("the NAO6 plugin does not load");
const plugin: Plugin = loaded.value;
const say = plugin.actions.find((a) => a.id === "say_text")!;

const sim = await startDefaultSimulator({ SIM_PORT: "0", SIM_MS_PER_CHAR: "0" });
const arrivals = new Map<string, (at: number) => void>();
const record = sim.received.push.bind(sim.received);
sim.received.push = (...items) => {
  const at = performance.now();
  for (const item of items) arrivals.get((item.message.msg as { data?: string } | undefined)?.data ?? "")?.(at);
  return record(...items);
};

const transport = new RosbridgeTransport({ url: sim.url });
await transport.connect();
const latencies: number[] = [];
for (let i = -500; i < DISPATCHES; i++) {
  const text = `line ${i}`;
  const started = performance.now();
  const arrived = new Promise<number>((ok) => arrivals.set(text, ok));
  await transport.dispatch(say, { text });
  const at = await arrived;
  arrivals.delete(text);
  // The first 500 warm the JIT and the socket; they are not counted.
  if (i >= 0) latencies.push(at - started);
}
report("dispatch → message received by the simulated robot", latencies, 2);
await transport.close();
await sim.close();
process.exit(0);
