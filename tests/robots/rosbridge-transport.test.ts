// Every action of the fixture NAO6 plugin through the real roslib client into
// the simulated robot over a real socket: the exact topic, type and payload
// received. Then services, timeouts, drops, reconnects and the heartbeat.
import { createHash } from "node:crypto";
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin, type PluginAction } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import type { Health } from "../../src/robots/transports/transport";
import { readTranscript } from "./support/replay";

const fixture = (() => {
  const loaded = loadPlugin(
    "nao6-ros2.json",
    readFileSync("tests/fixtures/hristudio-plugins/plugins/nao6-ros2.json", "utf8"),
  );
  if (!loaded.ok) throw new Error("fixture");
  return loaded.value as Plugin;
})();
const hostile = (readTranscript("02-hostile-text-roundtrip.jsonl")[4]!.frame as { msg: { data: string } }).msg.data;
const hostileSha = JSON.parse(
  readFileSync("tests/fixtures/rosbridge-transcripts/02-hostile-text-roundtrip.check.json", "utf8"),
).sent.sha256_utf8;

let sim: Simulator | null = null;
let transport: RosbridgeTransport | null = null;
afterEach(async () => {
  await transport?.close();
  await sim?.close();
  transport = sim = null;
});

const until = async (check: () => boolean, ms = 5000) => {
  const end = Date.now() + ms;
  while (!check()) {
    if (Date.now() > end) throw new Error("timed out waiting");
    await new Promise((r) => setTimeout(r, 5));
  }
};

async function setUp(options: Partial<ConstructorParameters<typeof RosbridgeTransport>[0]> = {}) {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(fixture, { msPerChar: 0 }) });
  transport = new RosbridgeTransport({ url: sim.url, backoffMs: { first: 50, max: 400 }, ...options });
  await transport.connect();
  return { sim, transport };
}

/** What the simulator received for one publish: the advertised type and the message. */
function lastPublish(sim: Simulator, topic: string) {
  const publishes = sim.received.filter((r) => r.message.op === "publish" && r.message.topic === topic);
  const advertise = sim.received.find((r) => r.message.op === "advertise" && r.message.topic === topic);
  return { count: publishes.length, type: advertise?.message.type, msg: publishes.at(-1)?.message.msg };
}

const parametersFor: Record<string, Record<string, unknown>> = {
  say_text: { text: hostile },
  say_with_emotion: { text: hostile, emotion: "happy" },
  walk_forward: { speed: 0.3 },
};

function expectedPayload(action: PluginAction) {
  if (action.id === "say_text") return { data: hostile };
  if (action.id === "say_with_emotion") return { data: `\\rspd=110\\\\vct=115\\${hostile}` };
  const mapping = (action.ros2 as { payloadMapping: { payload: unknown } }).payloadMapping;
  expect(JSON.stringify(mapping.payload)).not.toContain("{{");
  return mapping.payload;
}

describe("every action of the fixture NAO6 plugin through roslib", () => {
  const overRosbridge = fixture.actions.filter(
    (a) => a.ros2 && "payloadMapping" in a.ros2 && a.ros2.payloadMapping?.type !== "ssh",
  );
  const overSsh = fixture.actions.filter((a) => !overRosbridge.includes(a));

  it("covers all 20 actions: 14 over rosbridge, 6 over SSH", () => {
    expect([overRosbridge.length, overSsh.length]).toEqual([14, 6]);
  });

  it.each(overRosbridge.map((a) => [a.id, a] as const))(
    "%s arrives with its exact topic, type and payload",
    async (_, action) => {
      const { sim, transport } = await setUp();
      const ros2 = action.ros2 as { topic: string; messageType: string };
      const outcome = await transport.dispatch(action, parametersFor[action.id] ?? {});
      // The fixture declares no completion rules: taken in by the bridge, not confirmed done by the robot.
      expect(outcome).toEqual({
        status: "completed",
        detail: { topic: ros2.topic, confirmation: { by: "delivered", confirmed: false } },
      });
      await until(() => lastPublish(sim, ros2.topic).count === 1);
      const received = lastPublish(sim, ros2.topic);
      expect(received.type).toBe(ros2.messageType);
      expect(received.msg).toEqual(expectedPayload(action));
    },
  );

  it("the hostile text of transcript 02 arrives byte-identical", async () => {
    const { sim, transport } = await setUp();
    await transport.dispatch(fixture.actions.find((a) => a.id === "say_text")!, { text: hostile });
    await until(() => sim.state.lastSaid !== null);
    const data = (lastPublish(sim, "/speech").msg as { data: string }).data;
    expect(createHash("sha256").update(data, "utf8").digest("hex")).toBe(hostileSha);
    expect(sim.state.lastSaid).toBe(hostile);
  });

  it.each(overSsh.map((a) => [a.id, a] as const))(
    "%s is refused as an SSH action, and nothing is published",
    async (_, action) => {
      const { sim, transport } = await setUp();
      expect(await transport.dispatch(action, {})).toEqual({
        status: "failed",
        reason: `action "${action.id}" runs over SSH, not rosbridge`,
      });
      expect(sim.received.filter((r) => r.message.op === "publish")).toEqual([]);
    },
  );

  it("refuses bad parameters before sending anything", async () => {
    const { sim, transport } = await setUp();
    const walk = fixture.actions.find((a) => a.id === "walk_forward")!;
    expect(await transport.dispatch(walk, { speed: 3 })).toEqual({
      status: "failed",
      reason: '"Speed" must be at most 0.55',
    });
    expect(sim.received).toEqual([]);
  });
});

describe("service calls", () => {
  const service = (name: string, timeout = 2000, args: Record<string, string> = {}): PluginAction => ({
    id: name.slice(1),
    name,
    category: "test",
    timeout,
    parameterSchema: { type: "object", properties: { on: { type: "boolean" } } },
    ros2: { service: name, serviceType: name === "/set_led" ? "std_srvs/srv/SetBool" : "std_srvs/srv/Trigger", args },
  });

  it("completes with the response", async () => {
    const { transport } = await setUp();
    expect(await transport.dispatch(service("/set_led", 2000, { data: "{{on}}" }), { on: true })).toEqual({
      status: "completed",
      detail: {
        response: { success: true, message: "led=True" },
        confirmation: { by: "service_response", confirmed: true, source: "/set_led" },
      },
    });
  });

  it("fails with the robot's reason", async () => {
    const { transport } = await setUp();
    const outcome = await transport.dispatch(service("/broken"), {});
    expect(outcome).toEqual({
      status: "failed",
      reason: "service [/broken] responded with an error: error processing request: motor fault",
    });
  });

  it("times out at the plugin's timeout", async () => {
    const { transport } = await setUp();
    const outcome = await transport.dispatch(service("/slow_op", 300), {});
    // The service never answers in time: the outcome says so (how long it took is the machine's, not the test's).
    expect(outcome.status).toBe("timed_out");
  });
});

describe("connection health", () => {
  it("reports a drop at once, reconnects with backoff and subscribes again", async () => {
    const { sim, transport } = await setUp();
    const states: Health["state"][] = [];
    transport.onHealth((h) => states.push(h.state));
    const joints: unknown[] = [];
    transport.subscribe("/joint_states", "sensor_msgs/msg/JointState", (m) => joints.push(m));
    await until(() => joints.length > 2);
    sim.faults.dropConnections();
    await until(() => states.includes("disconnected"), 1000);
    await until(() => transport.health().state === "connected");
    const before = joints.length;
    await until(() => joints.length > before + 2);
    expect(states.slice(0, 3)).toEqual(["disconnected", "connecting", "connected"]);
  });

  it("a retryable action waits for the robot to come back; others fail at once", async () => {
    const { sim, transport } = await setUp();
    sim.faults.refuseConnections(true);
    sim.faults.dropConnections();
    await until(() => transport.health().state !== "connected");
    const stop = fixture.actions.find((a) => a.id === "stop_walking")!;
    expect(await transport.dispatch({ ...stop, retryable: false }, {})).toEqual({
      status: "failed",
      reason: expect.stringMatching(/^robot not connected: the robot's bridge closed the connection/),
    });
    const pending = transport.dispatch(stop, {});
    setTimeout(() => sim.faults.refuseConnections(false), 300);
    expect(await pending).toEqual({
      status: "completed",
      detail: { topic: "/cmd_vel", confirmation: { by: "delivered", confirmed: false } },
    });
  });

  it("the heartbeat notices a bridge that has stopped answering, and reconnects once it answers again", async () => {
    const { sim, transport } = await setUp({ heartbeatEveryMs: 100, heartbeatTimeoutMs: 150 });
    await until(() => transport.health().lastHeartbeatMs !== null);
    const states: Health["state"][] = [];
    transport.onHealth((h) => states.push(h.state));
    sim.faults.freeze(true);
    await until(() => states.includes("disconnected"), 2000);
    expect(transport.health().reason).toMatch(/stopped answering/);
    sim.faults.freeze(false);
    await until(() => transport.health().state === "connected");
  });

  it("the heartbeat is WebSocket ping/pong: it sends the bridge no op, so nothing reaches the bridge's log", async () => {
    const { sim, transport } = await setUp({ heartbeatEveryMs: 50 });
    await until(() => transport.health().lastHeartbeatMs !== null);
    await new Promise((r) => setTimeout(r, 300));
    expect(sim.received.filter((r) => r.message.op === "call_service")).toEqual([]);
    expect(sim.log).toEqual([]);
  });

  it("tells the trial an error the bridge reports in a status frame, without dropping the link", async () => {
    const { sim, transport } = await setUp();
    const problems: string[] = [];
    transport.onHealth((h) => h.problem && problems.push(h.problem));
    sim.faults.reportStatus("error", "Unable to load the manifest for package nao_msgs");
    await until(() => problems.length > 0);
    expect(problems).toEqual([
      "the robot's bridge reported an error: Unable to load the manifest for package nao_msgs",
    ]);
    expect(transport.health().state).toBe("connected");
  });
});
