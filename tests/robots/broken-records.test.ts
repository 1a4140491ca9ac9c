// A robot's faults stay with its own actions: every transport (rosbridge,
// simulated, SSH, HTTP), built where the runtime builds it (transportFor),
// given broken robot records (a key file that is not a key, an address that
// is not one, a host that refuses or never answers, a refused login) and
// every kind of action it carries. Each action fails with a plain reason, no
// error escapes (vitest fails the file on any unhandled rejection or uncaught
// exception), and a healthy robot beside them keeps being driven.
import { spawnSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { createServer as createHttpServer } from "node:http";
import { createServer, type Server, type Socket } from "node:net";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin, type PluginAction, type TransportKind } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { type DispatchOutcome, type TransportConfig, transportFor } from "../../src/robots/transports";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { freePort } from "../../src/store/embedded";
import { startSshd, type TestSshd } from "../support/sshd";

const waffle = (() => {
  const file = "turtlebot3-waffle.json";
  const loaded = loadPlugin(file, readFileSync(`tests/fixtures/hristudio-plugins/plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(loaded.errors.map((e) => e.reason).join("; "));
  return loaded.value as Plugin;
})();
// Not retried: a retryable action waits out its timeout for the robot to come back, and then it timed out.
const of = (id: string): PluginAction => ({
  ...waffle.actions.find((a) => a.id === id)!,
  retryable: false,
  timeout: 1500,
});
const none = { type: "object" as const, properties: {} };
const extra = (id: string, rest: Partial<PluginAction>): PluginAction => ({
  id,
  name: id,
  category: "test",
  parameterSchema: none,
  timeout: 1500,
  ...rest,
});

/** Every kind of action a transport carries, each with parameters it accepts. */
const KINDS: Record<string, [PluginAction, Record<string, unknown>]> = {
  "a topic message": [of("move_velocity"), { linear: 0.1, angular: 0 }],
  "a ROS 2 action goal": [of("move_to_pose"), { x: 0.1, y: 0, theta: 0 }],
  "a turn then a stop": [of("rotate_in_place"), { angle: 0.5 }],
  "a reading": [of("get_robot_state"), {}],
  "a service call": [extra("reset", { ros2: { service: "/reset", serviceType: "std_srvs/srv/Trigger" } }), {}],
  "an SSH command": [
    extra("wake_up", {
      ros2: {
        topic: "/ssh",
        messageType: "std_msgs/msg/String",
        payloadMapping: { type: "ssh", sshCommand: "qicli call ALMotion.wakeUp" },
      },
    }),
    {},
  ],
  "an HTTP request": [extra("say", { http: { method: "POST", url: "speech", body: { text: "hi" } } }), {}],
};
const ROS = ["a topic message", "a ROS 2 action goal", "a turn then a stop", "a reading", "a service call"];
const kindsOf: Record<TransportKind, string[]> = {
  rosbridge: ROS,
  simulated: ROS,
  ssh: ["an SSH command"],
  http: ["an HTTP request"],
};
const pluginFor = (transport: TransportKind): Plugin => ({
  robotId: "broken",
  name: "Broken robot",
  version: "1.0.0",
  pluginApiVersion: "1.0",
  transport,
  actions: [...waffle.actions, ...Object.values(KINDS).map(([a]) => a)],
});

// Words a wizard should never read: a stack, a system call, an object printed as such.
const UNPLAIN = /\n|\bat .*:\d+:\d+|\[object|undefined|getaddrinfo|\bE[A-Z]{4,}\b|Error:/;

let sshd: TestSshd;
let sim: Simulator;
let neighbour: RosbridgeTransport;
const servers: Server[] = [];
const held: Socket[] = [];
mkdirSync(".tmp", { recursive: true });
const dir = mkdtempSync(join(".tmp", "broken-records-"));
/** Ports nothing listens on, a host that takes connections and never says a word, HTTP servers that refuse. */
let closed: number;
let silent: number;
let forbidding: number;

async function listening(server: Server): Promise<number> {
  servers.push(server);
  await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
  return (server.address() as { port: number }).port;
}

beforeAll(async () => {
  sshd = await startSshd();
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(waffle) });
  neighbour = new RosbridgeTransport({ url: sim.url, plugin: waffle });
  await neighbour.connect();
  closed = await freePort();
  silent = await listening(createServer((socket) => void held.push(socket)));
  forbidding = await listening(createHttpServer((_, res) => res.writeHead(401).end("who are you?")));
  writeFileSync(join(dir, "notes.txt"), "this is not a key\n");
  spawnSync("ssh-keygen", ["-q", "-t", "ed25519", "-N", "", "-f", join(dir, "stranger")]);
}, 60_000);

afterAll(async () => {
  await neighbour?.close();
  await sim?.close();
  sshd?.stop();
  held.forEach((s) => s.destroy());
  servers.forEach((s) => s.close());
  rmSync(dir, { recursive: true, force: true });
});

type Expected = RegExp | "timed_out";
const ssh = (over: Partial<NonNullable<TransportConfig["ssh"]>>): TransportConfig => ({
  ssh: { host: "127.0.0.1", port: sshd.port, username: sshd.username, privateKeyFile: sshd.keyFile, ...over },
});
const ros = (url: () => string) => (kind: TransportKind) =>
  kind === "simulated" ? { simulatorUrl: url() } : { rosbridgeUrl: url() };

// [transport, the record's fault, its settings, what each action's outcome says]
const RECORDS: Array<[TransportKind, string, () => TransportConfig, Expected]> = [
  ...(["rosbridge", "simulated"] as const).flatMap(
    (kind): Array<[TransportKind, string, () => TransportConfig, Expected]> => [
      [kind, "an address that is not a URL", () => ros(() => "not a url")(kind), /not a URL/],
      [
        kind,
        "an address of another scheme",
        () => ros(() => "ftp://robot.local/")(kind),
        /"ftp:\/\/robot.local\/" is not a ws:\/\/ or wss:\/\/ or http:\/\/ or https:\/\/ address/,
      ],
      [
        kind,
        "a host that does not exist",
        () => ros(() => "ws://no-such-robot.invalid:9090")(kind),
        /no host named "no-such-robot.invalid"/,
      ],
      [kind, "a port nothing listens on", () => ros(() => `ws://127.0.0.1:${closed}`)(kind), /connection was refused/],
      [
        kind,
        "a bridge that refuses the connection",
        () => ros(() => `ws://127.0.0.1:${forbidding}`)(kind),
        /refused the connection \(HTTP 401\)/,
      ],
      [kind, "a host that never answers", () => ros(() => `ws://127.0.0.1:${silent}`)(kind), /did not answer in time/],
    ],
  ),
  [
    "ssh",
    "a key file that is not a key",
    () => ssh({ privateKeyFile: join(dir, "notes.txt") }),
    /does not hold a private key SSH can use/,
  ],
  [
    "ssh",
    "a key file that is not there",
    () => ssh({ privateKeyFile: join(dir, "missing") }),
    /cannot be read: there is no such file/,
  ],
  [
    "ssh",
    "a public key for a private one",
    () => ssh({ privateKeyFile: join(dir, "stranger.pub") }),
    /does not hold a private key SSH can use/,
  ],
  ["ssh", "a key the robot does not know", () => ssh({ privateKeyFile: join(dir, "stranger") }), /refused the login/],
  [
    "ssh",
    "a password the robot does not take",
    () => ssh({ privateKeyFile: undefined, password: "guess" }),
    /refused the login/,
  ],
  [
    "ssh",
    "a host that does not exist",
    () => ssh({ host: "no-such-robot.invalid" }),
    /no host named "no-such-robot.invalid"/,
  ],
  ["ssh", "a port out of range", () => ssh({ port: 70_000 }), /the SSH port 70000 is not a port number/],
  ["ssh", "a port nothing listens on", () => ssh({ port: closed }), /connection was refused/],
  ["ssh", "a host that never answers", () => ssh({ port: silent }), /did not answer in time/],
  ["http", "an address that is not a URL", () => ({ httpBaseUrl: "not a url" }), /"not a url" is not a URL/],
  [
    "http",
    "an address of another scheme",
    () => ({ httpBaseUrl: "ftp://robot.local/" }),
    /"ftp:\/\/robot.local\/" is not a http:\/\/ or https:\/\/ address/,
  ],
  [
    "http",
    "a host that does not exist",
    () => ({ httpBaseUrl: "http://no-such-robot.invalid/" }),
    /no host named "no-such-robot.invalid"|did not answer/,
  ],
  [
    "http",
    "a port nothing listens on",
    () => ({ httpBaseUrl: `http://127.0.0.1:${closed}/` }),
    /connection was refused/,
  ],
  [
    "http",
    "an API that refuses the login",
    () => ({ httpBaseUrl: `http://127.0.0.1:${forbidding}/` }),
    /answered HTTP 401: who are you\?/,
  ],
  // The request went out and nothing came back: the robot may have done it, so it timed out rather than failed.
  ["http", "a host that never answers", () => ({ httpBaseUrl: `http://127.0.0.1:${silent}/` }), "timed_out"],
];

describe("a broken robot record fails its own actions in plain words, and nothing else", () => {
  it.each(RECORDS)("%s: %s", { timeout: 60_000 }, async (kind, _fault, settings, expected) => {
    const plugin = pluginFor(kind);
    const choice = transportFor(plugin, settings());
    if (!choice.ok) throw new Error(choice.reason);
    const transport = choice.transport;
    // As the runtime does: connecting starts when the trial opens; the actions come once its first try is over.
    const tried = transport.connect().catch(() => undefined);
    await Promise.race([tried, expect.poll(() => transport.health().reason, { timeout: 15_000 }).toBeDefined()]);
    try {
      for (const name of kindsOf[kind]) {
        const [action, parameters] = KINDS[name]!;
        const outcome: DispatchOutcome = await transport.dispatch(action, parameters);
        if (expected === "timed_out") {
          expect(outcome.status, name).toBe("timed_out");
          continue;
        }
        expect(outcome.status, name).toBe("failed");
        const { reason } = outcome as { reason: string };
        expect(reason, name).toMatch(expected);
        expect(reason, name).not.toMatch(UNPLAIN);
      }
    } finally {
      await transport.close();
    }
    // The robot beside it is still driven.
    expect((await neighbour.dispatch(...KINDS["a topic message"]!)).status).toBe("completed");
  });
});
