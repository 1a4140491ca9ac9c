// The robot's own camera: the simulated robot publishes compressed images on
// the topic the plugin declares; the runtime's robot link subscribes through
// the real roslib client with the plugin's throttle_rate (the rate the network
// holds) and hands each frame on as base64 JPEG, until it is stopped.
import { readFileSync } from "node:fs";
import { afterEach, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { pluginRobot } from "../../src/runtime/robot-link";
import type { CameraFrame } from "../../src/runtime/robot";
import { CAMERA_TOPIC, simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";

const pluginFile = (name: string) => {
  const loaded = loadPlugin(name, readFileSync(`plugins/${name}`, "utf8"));
  if (!loaded.ok) throw new Error(`plugins/${name} does not load`);
  return loaded.value as Plugin;
};

let sim: Simulator | null = null;
let close: (() => void) | null = null;
afterEach(async () => {
  close?.();
  await sim?.close();
  sim = null;
  close = null;
});

const until = async (check: () => boolean, ms = 10_000) => {
  const end = Date.now() + ms;
  while (!check()) {
    if (Date.now() > end) throw new Error("timed out waiting");
    await new Promise((r) => setTimeout(r, 10));
  }
};

it.each(["simulated.json", "nao6-ros2.json"])("%s: the robot's camera, throttled, as JPEG frames", async (name) => {
  const plugin = pluginFile(name);
  expect(plugin.camera).toEqual({
    topic: CAMERA_TOPIC,
    messageType: "sensor_msgs/msg/CompressedImage",
    throttleRate: 200,
  });
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  const robot = pluginRobot(plugin, new RosbridgeTransport({ url: sim.url }));
  close = () => robot.close();
  const frames: CameraFrame[] = [];
  const stop = robot.watchCamera((frame) => frames.push(frame));
  await until(() => frames.length >= 3);
  // Asked of rosbridge with the plugin's throttle: the robot sends no faster than that, and with a queue of
  // one, so each interval's newest frame is sent at its end (a frame every 200 ms, not every third or fourth).
  const subscribe = sim.received
    .map((r) => r.message as { op?: string; topic?: string; throttle_rate?: number })
    .find((m) => m.op === "subscribe" && m.topic === CAMERA_TOPIC);
  expect(subscribe).toMatchObject({ throttle_rate: 200, queue_length: 1 });
  for (const frame of frames) {
    const bytes = Buffer.from(frame.data, "base64");
    expect(frame.format).toBe("jpeg");
    // A whole JPEG: start and end of image markers.
    expect([...bytes.subarray(0, 2)]).toEqual([0xff, 0xd8]);
    expect([...bytes.subarray(-2)]).toEqual([0xff, 0xd9]);
  }
  expect(new Set(frames.map((f) => f.data)).size).toBeGreaterThan(1);
  stop();
  await until(() => sim!.received.some((r) => (r.message as { op?: string; topic?: string }).op === "unsubscribe"));
  const after = frames.length;
  await new Promise((r) => setTimeout(r, 600));
  expect(frames.length).toBe(after);
});

it("a robot whose plugin declares no camera has none", () => {
  const plugin = pluginFile("turtlebot3-burger.json");
  expect(plugin.camera).toBeUndefined();
  const robot = pluginRobot(plugin, new RosbridgeTransport({ url: "ws://127.0.0.1:1" }));
  const frames: CameraFrame[] = [];
  robot.watchCamera((f) => frames.push(f))();
  robot.close();
  expect(frames).toEqual([]);
});
