// The simulated robot's wire against the recorded rosbridge frames, where
// Python clients notice: floats keep their ".0" (README G3; the recorded raw
// joint states say "velocity":[0.1,0.0]), NaN and Infinity are read as the
// literals Python's JSON reads and written null as rosbridge's message
// conversion writes them (ROS 1 and ROS 2 alike), and BatteryState has every
// field of sensor_msgs/msg/BatteryState. Raw text is compared here, on
// purpose: the point is what a non-JavaScript parser sees.
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { WebSocket } from "ws";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, transcriptRobot, type Simulator } from "../../src/robots/simulator";
import { readTranscript } from "./support/replay";

let sim: Simulator | null = null;
afterEach(async () => {
  await sim?.close();
  sim = null;
});

/** A raw client: sends text as given, keeps every frame's text. */
async function rawClient(url: string) {
  const frames: string[] = [];
  const socket = new WebSocket(url, { perMessageDeflate: false });
  socket.on("message", (data) => frames.push(data.toString()));
  await new Promise((ok, fail) => socket.once("open", ok).once("error", fail));
  return {
    frames,
    send: (text: string) => socket.send(text),
    close: () => socket.terminate(),
    on: (topic: string) => frames.filter((f) => f.includes(`"topic":"${topic.replace("/", "\\/")}"`)),
  };
}

describe("floats on the wire", () => {
  it("joint states keep 0.0 as the recorded server wrote them", async () => {
    const recorded = readTranscript("03-subscribe-throttle-unsubscribe.jsonl").find(
      (l) => l.dir === "recv" && (l.frame as { topic?: string }).topic === "/joint_states",
    ) as { raw?: string };
    expect(recorded.raw).toContain('"velocity":[0.1,0.0]');
    sim = await startSimulator({ port: 0, nodes: transcriptRobot() });
    const client = await rawClient(sim.url);
    client.send('{"op":"subscribe","topic":"/joint_states","type":"sensor_msgs/msg/JointState"}');
    await expect.poll(() => client.on("/joint_states").length).toBeGreaterThan(0);
    expect(client.on("/joint_states")[0]).toContain('"velocity":[0.1,0.0]');
    expect(client.on("/joint_states")[0]).toContain('"position":[');
    client.close();
  });

  it("a float sent as 1.0 comes back as 1.0, an integer field stays an integer", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const client = await rawClient(sim.url);
    client.send('{"op":"subscribe","topic":"/f","type":"std_msgs/msg/Float64"}');
    client.send('{"op":"subscribe","topic":"/i","type":"std_msgs/msg/Int32"}');
    client.send('{"op":"publish","topic":"/f","msg":{"data":1.0}}');
    client.send('{"op":"publish","topic":"/i","msg":{"data":7}}');
    await expect.poll(() => client.frames.length).toBe(2);
    expect(client.on("/f")).toEqual(['{"op":"publish","topic":"\\/f","msg":{"data":1.0}}']);
    expect(client.on("/i")).toEqual(['{"op":"publish","topic":"\\/i","msg":{"data":7}}']);
    client.close();
  });
});

describe("NaN and Infinity, read as Python's JSON has them, written null as rosbridge does", () => {
  it.each([["NaN"], ["Infinity"], ["-Infinity"]])(
    "%s in a float field arrives and is written back as null",
    async (literal) => {
      sim = await startSimulator({ port: 0, nodes: [] });
      const client = await rawClient(sim.url);
      client.send('{"op":"subscribe","topic":"/f","type":"std_msgs/msg/Float64"}');
      client.send(`{"op":"publish","topic":"/f","msg":{"data":${literal}}}`);
      await expect.poll(() => client.on("/f").length).toBe(1);
      expect(client.on("/f")[0]).toBe('{"op":"publish","topic":"\\/f","msg":{"data":null}}');
      client.close();
    },
  );

  it("NaN in an integer field is refused (to the log), and nothing is published", async () => {
    sim = await startSimulator({ port: 0, nodes: [] });
    const client = await rawClient(sim.url);
    client.send('{"op":"subscribe","topic":"/i","type":"std_msgs/msg/Int32"}');
    client.send('{"op":"publish","topic":"/i","msg":{"data":NaN}}');
    await expect.poll(() => sim!.log.length).toBe(1);
    expect(sim.log[0]!.text).toMatch(/int32/);
    expect(client.frames).toEqual([]);
    client.close();
  });
});

describe("the battery", () => {
  const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;

  it("publishes every field of sensor_msgs/msg/BatteryState, in the message's order, null where unmeasured", async () => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { batteryHz: 20 }) });
    const client = await rawClient(sim.url);
    client.send('{"op":"subscribe","topic":"/battery","type":"sensor_msgs/msg/BatteryState"}');
    await expect.poll(() => client.on("/battery").length).toBeGreaterThan(0);
    const raw = client.on("/battery")[0]!;
    const fields = [...raw.slice(raw.indexOf('"msg":')).matchAll(/"([a-z_]+)":/g)].map((m) => m[1]);
    expect(fields.filter((f) => !["msg", "header", "stamp", "sec", "nanosec", "frame_id"].includes(f!))).toEqual([
      "voltage",
      "temperature",
      "current",
      "charge",
      "capacity",
      "design_capacity",
      "percentage",
      "power_supply_status",
      "power_supply_health",
      "power_supply_technology",
      "present",
      "cell_voltage",
      "cell_temperature",
      "location",
      "serial_number",
    ]);
    expect(raw).toContain('"temperature":null');
    expect(raw).toContain('"design_capacity":null');
    expect(raw).not.toMatch(/NaN|Infinity/);
    expect(raw).toContain('"capacity":2.25');
    expect(raw).toContain('"power_supply_status":2,');
    client.close();
  });
});
