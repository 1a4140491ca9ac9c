// The simulated robot with the NAO6 plugin: its topics, the record of what it
// received, speech timing, joint states and battery, and injected faults.
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { WebSocket } from "ws";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { parsePythonJson } from "../../src/core/robots/python-json";

const nao6 = (() => {
  const loaded = loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8"));
  if (!loaded.ok) throw new Error("nao6 plugin");
  return loaded.value as Plugin;
})();

let sim: Simulator | null = null;
afterEach(async () => {
  await sim?.close();
  sim = null;
});

async function client(url: string) {
  const frames: Array<Record<string, any>> = [];
  const socket = new WebSocket(url);
  // As our transport reads rosbridge: an older rosbridge writes NaN literals.
  socket.on("message", (data) => frames.push(parsePythonJson(data.toString()) as Record<string, any>));
  await new Promise((resolve, reject) => socket.once("open", resolve).once("error", reject));
  const send = (frame: unknown) => socket.send(JSON.stringify(frame));
  const until = async (check: () => boolean, ms = 3000) => {
    const end = Date.now() + ms;
    while (!check()) {
      if (Date.now() > end) throw new Error("timed out");
      await new Promise((r) => setTimeout(r, 5));
    }
  };
  return { socket, frames, send, until };
}

describe("the simulated NAO6", () => {
  it("knows every topic the NAO6 plugin publishes to, with its type", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6, { batteryHz: 5 }) });
    expect(sim.graph.typeOf("/speech")).toBe("std_msgs/String");
    expect(sim.graph.typeOf("/cmd_vel")).toBe("geometry_msgs/Twist");
    expect(sim.graph.typeOf("/animation")).toBe("std_msgs/String");
    expect(sim.graph.typeOf("/joint_angles")).toBe("naoqi_bridge_msgs/JointAnglesWithSpeed");
    expect(sim.url).toMatch(/^ws:\/\/127\.0\.0\.1:\d+$/);
  });

  it("records what it receives and finishes speech after a time proportional to the text", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6, { msPerChar: 10 }) });
    const c = await client(sim.url);
    c.send({ op: "subscribe", topic: "/speech_done", type: "std_msgs/msg/String" });
    const text = "x".repeat(30);
    const sentAt = Date.now();
    c.send({ op: "publish", topic: "/speech", msg: { data: text } });
    await c.until(() => sim!.state.speaking === text);
    await c.until(() => c.frames.some((f) => f.topic === "/speech_done"));
    expect(Date.now() - sentAt).toBeGreaterThanOrEqual(290);
    expect(c.frames).toEqual([{ op: "publish", topic: "/speech_done", msg: { data: `said: ${text}` } }]);
    expect(sim.received.map((r) => r.message.op)).toEqual(["subscribe", "publish"]);
    expect(sim.state.lastSaid).toBe(text);
    c.socket.close();
  });

  it("publishes joint states and battery at the configured rates", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6, { jointStatesHz: 20, batteryHz: 10 }) });
    const c = await client(sim.url);
    c.send({ op: "subscribe", topic: "/joint_states", type: "sensor_msgs/msg/JointState" });
    c.send({ op: "subscribe", topic: "/battery", type: "sensor_msgs/BatteryState" });
    await new Promise((r) => setTimeout(r, 1000));
    const joints = c.frames.filter((f) => f.topic === "/joint_states").length;
    const battery = c.frames.filter((f) => f.topic === "/battery");
    expect(joints).toBeGreaterThanOrEqual(12);
    expect(joints).toBeLessThanOrEqual(22);
    expect(battery.length).toBeGreaterThanOrEqual(6);
    expect(battery[0]!.msg.percentage).toBeGreaterThan(0.99);
    c.socket.close();
  });

  it("moves its joints through a wave and back, so the joint plot shows it", async () => {
    const loaded = loadPlugin("simulated.json", readFileSync("plugins/simulated.json", "utf8"));
    if (!loaded.ok) throw new Error("simulated plugin");
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(loaded.value as Plugin, { jointStatesHz: 20 }) });
    const c = await client(sim.url);
    c.send({ op: "subscribe", topic: "/joint_states", type: "sensor_msgs/msg/JointState" });
    const rightArm = () =>
      c.frames
        .filter((f) => f.topic === "/joint_states")
        .map((f) => f.msg.position[f.msg.name.indexOf("RShoulderPitch")]);
    await c.until(() => rightArm().length > 0);
    c.send({ op: "publish", topic: "/gesture", msg: { data: "wave" } });
    // Raised well above its standing angle (1.4 rad), then back down to it.
    await c.until(() => rightArm().some((a) => a < 0));
    await c.until(() => rightArm().at(-1) === 1.4);
    expect(new Set(rightArm()).size).toBeGreaterThan(10);
    c.socket.close();
  });

  it("mirrors gestures into its state (the robot view reads it)", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6) });
    const c = await client(sim.url);
    c.send({ op: "publish", topic: "/animation", msg: { data: "animations/Stand/Gestures/Hey_1" } });
    c.send({
      op: "publish",
      topic: "/joint_angles",
      msg: { joint_names: ["HeadPitch"], joint_angles: [0.44], speed: 0.1, relative: 0 },
    });
    await c.until(() => sim!.state.headPitch > 0.4);
    expect(sim.state.animation).toBe("animations/Stand/Gestures/Hey_1");
    c.socket.close();
  });
});

describe("injected faults", () => {
  it("drops every socket without a close frame", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6) });
    const c = await client(sim.url);
    const closed = new Promise<number>((resolve) => c.socket.once("close", resolve));
    sim.faults.dropConnections();
    expect(await closed).toBe(1006);
  });

  it("refuses new connections while asked to", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6) });
    sim.faults.refuseConnections(true);
    await expect(client(sim.url)).rejects.toThrow(/503/);
    sim.faults.refuseConnections(false);
    (await client(sim.url)).socket.close();
  });

  it("delays its replies", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao6) });
    sim.faults.delayReplies(200);
    const c = await client(sim.url);
    const t = Date.now();
    c.send({ op: "call_service", id: "w", service: "/wake_up" });
    await c.until(() => c.frames.length > 0);
    expect(Date.now() - t).toBeGreaterThanOrEqual(190);
    expect(c.frames[0]).toMatchObject({ id: "w", result: true });
    c.socket.close();
  });
});
