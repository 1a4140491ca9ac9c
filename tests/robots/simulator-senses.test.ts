// The simulated robot senses: a stimulus from its Robot page's control (a
// roslib client publishing on STIMULUS_TOPIC, as the page does) reaches a
// roslib subscriber on the event's own topic as the real message type; and
// the runtime's watcher (robot-senses.ts), over the real rosbridge transport,
// makes exactly one Sensed of a touch (none of its release), of a phrase
// heard well enough, and of someone stepping close.
import { readFileSync } from "node:fs";
import * as ROSLIB from "roslib";
import { afterEach, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin, type Sensed } from "../../src/core/plugins";
import { type Sensable, SENSABLE_TOPIC, type Stimulus, STIMULUS_TOPIC } from "../../src/core/robots/stimulus";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { watchSenses } from "../../src/runtime/robot-senses";

const plugin = (loadPlugin("simulated.json", readFileSync("plugins/simulated.json", "utf8")) as { value: Plugin })
  .value;

let sim: Simulator | null = null;
const cleanups: Array<() => void | Promise<void>> = [];
afterEach(async () => {
  for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
  await sim?.close();
  sim = null;
});

async function start() {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  const ros = new ROSLIB.Ros({ url: sim.url });
  await new Promise<void>((ok, fail) => {
    ros.on("connection", () => ok());
    ros.on("error", (e) => fail(new Error(`Could not reach the simulated robot at ${sim!.url}: ${String(e)}`)));
  });
  cleanups.push(() => ros.close());
  const control = new ROSLIB.Topic({ ros, name: STIMULUS_TOPIC, messageType: "std_msgs/msg/String" });
  const fire = (stimulus: Stimulus) => control.publish({ data: JSON.stringify(stimulus) });
  /** Every message on a topic, subscribed as the given type. */
  const heard = (name: string, messageType: string) => {
    const messages: Array<Record<string, unknown>> = [];
    new ROSLIB.Topic({ ros, name, messageType }).subscribe((m) => messages.push(m as Record<string, unknown>));
    return messages;
  };
  return { ros, fire, heard };
}

/** Until the simulator has the page's subscription and publisher: fire only then, or the stimulus is lost. */
const subscribed = (topic: string) =>
  expect
    .poll(() =>
      sim!.received.some(
        (r) =>
          (r.message as { op?: string; topic?: string }).op === "subscribe" &&
          (r.message as { topic?: string }).topic === topic,
      ),
    )
    .toBe(true);

describe("the simulated robot's senses over a real socket", () => {
  it("lists what it can be made to sense", async () => {
    const { heard } = await start();
    const lists = heard(SENSABLE_TOPIC, "std_msgs/msg/String");
    await expect.poll(() => lists.length, { timeout: 5000 }).toBeGreaterThan(0);
    const list = JSON.parse(lists[0]!.data as string) as Sensable[];
    expect(list.map((s) => s.id)).toEqual(plugin.events!.map((e) => e.id));
    expect(list.find((s) => s.id === "heard_ready")).toEqual({
      id: "heard_ready",
      name: 'Heard "ready"',
      kind: "heard",
    });
  });

  it("a touch, a phrase and someone close arrive as the real message types", async () => {
    const { fire, heard } = await start();
    const head = heard("/head_touch", "naoqi_bridge_msgs/msg/HeadTouch");
    const words = heard("/word_recognized", "naoqi_bridge_msgs/msg/WordRecognized");
    const sonar = heard("/sonar/left", "sensor_msgs/msg/Range");
    await subscribed("/word_recognized");
    fire({ event: "head_front_touched", touch: true });
    await expect
      .poll(() => head)
      .toEqual([
        { button: 1, state: 1 },
        { button: 1, state: 0 },
      ]);
    fire({ event: "heard_ready", heard: "ready", confidence: 0.8 });
    await expect.poll(() => words).toEqual([{ words: ["ready"], confidence_values: [0.8] }]);
    // Far until someone steps close: a whole Range, stamped by the robot.
    await expect.poll(() => sonar.length).toBeGreaterThan(0);
    expect(sonar[0]).toMatchObject({ header: { stamp: { sec: expect.any(Number) } }, radiation_type: 0 });
    expect(sonar[0]!.range as number).toBeGreaterThan(0.7);
    fire({ event: "someone_close_left", near: true });
    await expect.poll(() => sonar.at(-1)!.range as number).toBeLessThan(0.5);
  });

  it("the runtime's watcher: one Sensed for a touch and its release, one for a phrase heard, none for one misheard", async () => {
    const { fire, heard } = await start();
    const transport = new RosbridgeTransport({ url: sim!.url });
    cleanups.push(() => transport.close());
    await transport.connect();
    const sensed: Sensed[] = [];
    cleanups.push(watchSenses(transport, plugin, (s) => sensed.push(s)));
    const head = heard("/head_touch", "naoqi_bridge_msgs/msg/HeadTouch");
    const words = heard("/word_recognized", "naoqi_bridge_msgs/msg/WordRecognized");
    // The watcher is subscribed once its transport has asked for the topic.
    await expect
      .poll(() => sim!.received.filter((r) => (r.message as { topic?: string }).topic === "/head_touch").length)
      .toBeGreaterThanOrEqual(2);
    await subscribed("/word_recognized");
    fire({ event: "head_touched", touch: true });
    // The release has been published (the page's subscriber saw it): still the one event.
    await expect.poll(() => head.length).toBe(2);
    fire({ event: "heard_ready", heard: "Ready", confidence: 0.3 });
    fire({ event: "heard_ready", heard: "Ready", confidence: 0.9 });
    await expect.poll(() => words.length).toBe(2);
    await expect.poll(() => sensed.map((s) => s.event)).toEqual(["head_touched", "heard_ready"]);
    expect(sensed[0]).toMatchObject({ message: { button: 2, state: 1 } });
    expect(sensed[1]).toMatchObject({ message: { words: ["Ready"], confidence_values: [0.9] } });
  });

  it("someone close for the plugin's second is one Sensed, at the robot's stamp", async () => {
    const { fire } = await start();
    const transport = new RosbridgeTransport({ url: sim!.url });
    cleanups.push(() => transport.close());
    await transport.connect();
    const sensed: Sensed[] = [];
    // A clock far from the robot's: a stamped message is timed by its stamp, never by this.
    cleanups.push(
      watchSenses(
        transport,
        plugin,
        (s) => sensed.push(s),
        () => 0,
      ),
    );
    await subscribed("/sonar/left");
    fire({ event: "someone_close_left", near: true });
    await expect.poll(() => sensed.length, { timeout: 10_000 }).toBe(1);
    const [one] = sensed;
    const { stamp } = (one!.message as { header: { stamp: { sec: number; nanosec: number } } }).header;
    expect(one).toMatchObject({ event: "someone_close_left", at: stamp.sec * 1000 + Math.floor(stamp.nanosec / 1e6) });
    expect((one!.message as { range: number }).range).toBeLessThan(0.5);
  });
});
