// One contract, every transport: the same behaviours checked against
// rosbridge (roslib → the simulated robot), SSH (a real sshd) and HTTP (a
// real server), each over a real loopback socket.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { afterAll, describe, expect, it } from "vitest";
import type { PluginAction } from "../../src/core/plugins";
import { simulatedRobot, startSimulator } from "../../src/robots/simulator";
import { HttpTransport } from "../../src/robots/transports/http";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { SshTransport } from "../../src/robots/transports/ssh";
import type { Transport } from "../../src/robots/transports/transport";
import { readFileSync } from "node:fs";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { startSshd } from "../support/sshd";

const HOSTILE = `She said "hi" {{text}} $(rm -rf /) \`id\` '; echo ' \\ \n\t 🪨 赤い石 \u2028 end`;
const textSchema = { type: "object" as const, properties: { text: { type: "string" } }, required: ["text"] };
const none = { type: "object" as const, properties: {} };

interface Rig {
  transport: Transport;
  say: PluginAction;
  fails: PluginAction;
  slow: PluginAction;
  /** Texts the robot received through `say`, exactly. */
  heard(): string[];
  /** The robot gone from the network, and back. */
  drop(): void;
  restore(): Promise<void>;
  close(): Promise<void>;
}

async function rosbridgeRig(): Promise<Rig> {
  const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
  const sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao) });
  const call = (id: string, service: string, timeout?: number): PluginAction => ({
    id,
    name: id,
    category: "test",
    parameterSchema: none,
    timeout,
    ros2: { service, serviceType: "std_srvs/srv/Trigger" },
  });
  return {
    transport: new RosbridgeTransport({ url: sim.url, backoffMs: { first: 100, max: 200 } }),
    say: nao.actions.find((a) => a.id === "say_text")!,
    fails: call("broken", "/broken"),
    slow: call("slow", "/slow_op", 300),
    heard: () =>
      sim.received
        .filter((r) => r.message.op === "publish" && r.message.topic === "/speech")
        .map((r) => (r.message.msg as { data: string }).data),
    drop: () => {
      sim.faults.refuseConnections(true);
      sim.faults.dropConnections();
    },
    restore: async () => sim.faults.refuseConnections(false),
    close: () => sim.close(),
  };
}

async function sshRig(): Promise<Rig> {
  const sshd = await startSshd();
  const command = (id: string, sshCommand: string, schema = none, timeout?: number): PluginAction => ({
    id,
    name: id,
    category: "test",
    parameterSchema: schema,
    timeout,
    ros2: { topic: "/ssh", messageType: "std_msgs/msg/String", payloadMapping: { type: "ssh", sshCommand } },
  });
  return {
    transport: new SshTransport({
      host: "127.0.0.1",
      port: sshd.port,
      username: sshd.username,
      privateKeyFile: sshd.keyFile,
      backoffMs: { first: 100, max: 200 },
    }),
    say: command("say", "qicli call ALTextToSpeech.say {{text}}", textSchema),
    fails: command("fails", "qicli call fail"),
    slow: command("slow", "qicli call slow", none, 300),
    heard: () =>
      sshd
        .calls()
        .filter((c) => c[1] === "ALTextToSpeech.say")
        .map((c) => c[2]!),
    drop: () => sshd.stop(),
    restore: () => sshd.restart(),
    close: async () => sshd.stop(),
  };
}

async function httpRig(): Promise<Rig> {
  const heard: string[] = [];
  const server: Server = createServer((req, res) => {
    let body = "";
    req.on("data", (d) => (body += d));
    req.on("end", () => {
      if (req.url === "/speech") heard.push((JSON.parse(body) as { text: string }).text);
      if (req.url === "/fail") return res.writeHead(500).end("motor fault");
      if (req.url === "/slow") return void setTimeout(() => res.end("late"), 2000);
      res.end("ok");
    });
  });
  await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
  const port = (server.address() as AddressInfo).port;
  const base = `http://127.0.0.1:${port}/`;
  const request = (
    id: string,
    url: string,
    body?: Record<string, string>,
    schema = none,
    timeout?: number,
  ): PluginAction => ({
    id,
    name: id,
    category: "test",
    parameterSchema: schema,
    timeout,
    http: { method: "POST", url, body },
  });
  return {
    transport: new HttpTransport({ baseUrl: base, heartbeatEveryMs: 200 }),
    say: request("say", "speech", { text: "{{text}}" }, textSchema),
    fails: request("fails", "fail"),
    slow: request("slow", "slow", undefined, none, 300),
    heard: () => heard,
    drop: () => {
      server.close();
      server.closeAllConnections();
    },
    restore: () => new Promise<void>((ok) => server.listen(port, "127.0.0.1", ok)),
    close: async () => void server.close(),
  };
}

describe.each([
  ["rosbridge", rosbridgeRig],
  ["ssh", sshRig],
  ["http", httpRig],
])("the %s transport keeps the transport contract", (_name, makeRig) => {
  let rig: Rig;
  afterAll(async () => {
    await rig?.transport.close();
    await rig?.close();
  });

  it("connects and completes an action, delivering hostile text exactly", async () => {
    rig = await makeRig();
    await rig.transport.connect();
    expect(rig.transport.health().state).toBe("connected");
    expect((await rig.transport.dispatch(rig.say, { text: HOSTILE })).status).toBe("completed");
    await expect.poll(() => rig.heard()).toEqual([HOSTILE]);
  });

  it("reports a failure with the robot's reason", async () => {
    const outcome = await rig.transport.dispatch(rig.fails, {});
    expect(outcome.status).toBe("failed");
    expect((outcome as { reason: string }).reason.length).toBeGreaterThan(0);
  });

  it("times out within the action's timeout", async () => {
    expect(await rig.transport.dispatch(rig.slow, {})).toMatchObject({ status: "timed_out" });
  });

  it("refuses parameters the action does not declare, and sends nothing", async () => {
    const before = rig.heard().length;
    expect((await rig.transport.dispatch(rig.say, { text: "x", volume: 11 })).status).toBe("failed");
    expect(rig.heard().length).toBe(before);
  });

  it("reports a dropped connection at once", async () => {
    const states: string[] = [];
    rig.transport.onHealth((h) => states.push(h.state));
    rig.drop();
    await expect.poll(() => states.includes("disconnected"), { timeout: 5000 }).toBe(true);
  });

  it("fails an action at once while the robot is away, but holds a retryable one until the robot is back", async () => {
    expect(
      (await rig.transport.dispatch({ ...rig.say, retryable: false, timeout: 5000 }, { text: "not now" })).status,
    ).toBe("failed");
    const held = rig.transport.dispatch(
      { ...rig.say, retryable: true, timeout: 20_000 },
      { text: "when you are back" },
    );
    await new Promise((r) => setTimeout(r, 400));
    await rig.restore();
    expect(await held).toMatchObject({ status: "completed" });
    await expect.poll(() => rig.heard()).toContain("when you are back");
    expect(rig.heard()).not.toContain("not now");
  });

  it("times out a retryable action when the robot stays away", async () => {
    rig.drop();
    await expect.poll(() => rig.transport.health().state, { timeout: 5000 }).not.toBe("connected");
    expect(
      await rig.transport.dispatch({ ...rig.say, retryable: true, timeout: 600 }, { text: "never" }),
    ).toMatchObject({ status: "timed_out" });
    await rig.restore();
  });
});
