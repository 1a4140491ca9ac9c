// HRIStudio's plugin format as its files use it (templated topics, service
// mappings, expressions inside {{ }}), loaded from one file and sent through
// the real roslib client to the simulated robot over a real socket: the frame
// each action puts on the wire, byte for byte, and the actions that load
// unsupported, with why.
import { readFileSync } from "node:fs";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { loadPlugin, portability, unavailableActions, type Plugin } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";

const FILE = "format-constructs.json";
const loaded = loadPlugin(FILE, readFileSync(`tests/fixtures/plugins/${FILE}`, "utf8"));
if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
const plugin: Plugin = loaded.value;
const action = (id: string) => plugin.actions.find((a) => a.id === id)!;

let sim: Simulator;
let transport: RosbridgeTransport;
beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  transport = new RosbridgeTransport({ url: sim.url, plugin });
  await transport.connect();
});
afterAll(async () => {
  await transport.close();
  await sim.close();
});

/** The last publish or call_service frame: where it went and its message as JSON text. */
function lastFrame(): [string, string] {
  const frame = sim.received.filter((r) => r.message.op === "publish" || r.message.op === "call_service").at(-1)!;
  const m = frame.message;
  return m.op === "publish" ? [String(m.topic), JSON.stringify(m.msg)] : [String(m.service), JSON.stringify(m.args)];
}

describe("HRIStudio-format constructs through the simulated robot", () => {
  it.each<[string, string, Record<string, unknown>, string, string]>([
    ["templated topic", "set_led_color", { group: "chest", color: "red" }, "/leds/chest/color", '{"data":"red"}'],
    ["templated topic, open value", "say_as", { voice: "kid", text: "hi" }, "/speech/kid", '{"data":"hi"}'],
    ["service mapping without arguments", "wake_up", {}, "/naoqi_driver/ALMotion/wakeUp", "{}"],
    [
      "service mapping, templated, with an expression argument",
      "set_stiffness",
      { chain: "head", level: 0.8, locked: false },
      "/naoqi_driver/stiffness/head",
      '{"data":true}',
    ],
    [
      "? : and === in text, unary minus, math.round and /",
      "point_arm",
      { arm: "right", angle: 0.5, speed: 0.123 },
      "/joint_angles",
      '{"joint_names":["RShoulderPitch"],"joint_angles":[-0.5],"speed":0.12}',
    ],
    [
      '"-{{speed}}" in a float field, nested ? :, math.min and math.abs',
      "walk_back",
      { speed: 0.1, turn: "right", rate: -2 },
      "/cmd_vel",
      '{"linear":{"x":-0.1,"y":0,"z":0},"angular":{"x":0,"y":0,"z":-1}}',
    ],
    [
      "% + - * / || < <= > == != ! && !== math.floor math.ceil math.max in one text",
      "count",
      { n: 5, quiet: false },
      "/speech",
      '{"data":"2|6|4|10|1.25|true|false|false|true|true|false|true|2-3|10|many"}',
    ],
    [
      "nested 32 levels (the limit)",
      "deep",
      { n: 0.25 },
      "/cmd_vel",
      '{"linear":{"x":0.25,"y":0,"z":0},"angular":{"x":0,"y":0,"z":0}}',
    ],
  ])("%s", async (_, id, parameters, to, message) => {
    const outcome = await transport.dispatch(action(id), parameters);
    expect(outcome.status).toBe("completed");
    expect(lastFrame()).toEqual([to, message]);
  });

  it("logs the service's reply in the completion detail", async () => {
    expect(await transport.dispatch(action("wake_up"), {})).toEqual({
      status: "completed",
      detail: {
        response: { success: true, message: "" },
        confirmation: { by: "service_response", confirmed: true, source: "/naoqi_driver/ALMotion/wakeUp" },
      },
    });
  });

  it("sends nothing when a value makes no ROS name, and says so", async () => {
    const before = sim.received.length;
    expect(await transport.dispatch(action("say_as"), { voice: "../admin", text: "hi" })).toEqual({
      status: "failed",
      reason: '/speech/{voice}: with voice "../admin" it is "/speech/../admin", which is not a ROS name',
    });
    expect(sim.received.slice(before)).toEqual([]);
  });
});

describe("the constructs file", () => {
  it("loads with exactly the unsupported actions it should have, and why", () => {
    expect(unavailableActions(plugin)).toEqual([
      {
        actionId: "shout",
        path: "/actions/7/ros2/payloadMapping/payload/data",
        reason:
          'template "{{text.toUpperCase()}}" at character 7: unexpected "." (at ros2/payloadMapping/payload/data)',
      },
      {
        actionId: "too_deep",
        path: "/actions/9/ros2/payloadMapping/payload/linear/x",
        reason: `template "{{${"(".repeat(33)}n${")".repeat(33)}}}" at character 35: nested more than 32 levels deep (at ros2/payloadMapping/payload/linear/x)`,
      },
      {
        actionId: "sonar",
        path: "/actions/10/ros2/topic",
        reason: 'its topic /sonar/{side}: with side "2nd" it is "/sonar/2nd", which is not a ROS name',
      },
    ]);
  });

  it("knows every topic and service a templated action can reach", () => {
    const experiment = {
      steps: [
        {
          actions: [
            { id: "1", type: "format-constructs.set_led_color", parameters: { group: "eyes", color: "red" } },
            { id: "2", type: "format-constructs.set_stiffness", parameters: { chain: "head", level: 1 } },
            { id: "3", type: "format-constructs.say_as", parameters: { voice: "kid", text: "hi" } },
          ],
        },
      ],
    };
    expect(portability(experiment, plugin).actions.map((a) => [a.actionId, a.status, a.reaches])).toEqual([
      ["1", "supported", ["/leds/eyes/color", "/leds/chest/color"]],
      ["2", "supported", ["/naoqi_driver/stiffness/head", "/naoqi_driver/stiffness/body"]],
      ["3", "supported", undefined],
    ]);
  });

  it.each(["nao6-ros2.json", "turtlebot3-burger.json", "turtlebot3-waffle.json"])(
    "HRIStudio's %s still loads with no action unsupported for the new format",
    (file) => {
      const hristudio = loadPlugin(file, readFileSync(`tests/fixtures/hristudio-plugins/plugins/${file}`, "utf8"));
      expect(hristudio.ok).toBe(true);
      if (hristudio.ok)
        expect(unavailableActions(hristudio.value).filter((u) => /template|ROS name/.test(u.reason))).toEqual([]);
    },
  );
});
