// The simulated robot: a rosbridge v2 WebSocket server (ROS 2 flavour) with a
// simulated ROS graph behind it. It records every message clients send, and
// faults can be injected for tests: drop every socket, delay what it sends,
// refuse new connections.
import { WebSocketServer, type WebSocket } from "ws";
import { Connection } from "./connection";
import { RosGraph } from "./graph";
import { encode } from "./wire";
import { initialState, type RobotState } from "../../core/robots/robot-state";
import type { RobotNode } from "./nodes";
import { startSimulatedSsh, type SimulatedSsh, type SimulatedSshOptions } from "./ssh";

export interface SimulatorOptions {
  host?: string;
  /** 0 picks a free port. */
  port?: number;
  nodes: RobotNode[];
  /** Also answer the plugin's NAOqi commands over SSH, on the same robot state. */
  ssh?: Omit<SimulatedSshOptions, "host">;
  /**
   * A refused op (a subscribe or advertise of a type it does not know, a bad publish…) is also told to its
   * client as an error `status` frame, as rosbridge's protocol.md describes. Off by default: the recorded
   * servers only log it (README G1).
   */
  statusFrames?: boolean;
}

export interface Received {
  /** Milliseconds since the simulator started. */
  at: number;
  connection: string;
  message: Record<string, unknown>;
}

export interface Simulator {
  url: string;
  port: number;
  graph: RosGraph;
  state: RobotState;
  /** The SSH side, when asked for. */
  ssh: SimulatedSsh | null;
  /** Every message clients sent, parsed, in arrival order. */
  received: Received[];
  /** How many clients are connected now. */
  connections(): number;
  /** What the real server would only have written to its log. */
  log: Array<{ at: number; connection: string; text: string }>;
  faults: {
    dropConnections(): void;
    refuseConnections(refuse: boolean): void;
    delayReplies(ms: number): void;
    /** Reads nothing from any socket (no frames, no pings answered) while on, as a stopped process would; sockets stay open. */
    freeze(on: boolean): void;
    /** A `status` frame to every client, as rosbridge's protocol describes (the recorded servers never send one: README G1). */
    reportStatus(level: "error" | "warning" | "info", msg: string): void;
  };
  close(): Promise<void>;
}

export async function startSimulator(options: SimulatorOptions): Promise<Simulator> {
  const t0 = performance.now();
  const at = () => Math.round((performance.now() - t0) * 1000) / 1000;
  const graph = new RosGraph();
  const state = initialState();
  const stops = options.nodes.map((node) => node(graph, state));
  let refuse = false;
  let delay = 0;
  let frozen = false;
  let next = 0;
  const sockets = new Set<WebSocket>();
  const server = new WebSocketServer({
    host: options.host ?? "127.0.0.1",
    port: options.port ?? 9090,
    perMessageDeflate: false,
    verifyClient: (_, accept) => accept(!refuse, 503, "refused by fault injection"),
  });
  await new Promise<void>((resolve, reject) => server.once("listening", resolve).once("error", reject));
  const port = (server.address() as { port: number }).port;
  const ssh = options.ssh
    ? await startSimulatedSsh({ host: options.host ?? "127.0.0.1", ...options.ssh }, state)
    : null;
  const sim: Simulator = {
    url: `ws://${options.host ?? "127.0.0.1"}:${port}`,
    port,
    graph,
    state,
    ssh,
    received: [],
    connections: () => sockets.size,
    log: [],
    faults: {
      dropConnections: () => sockets.forEach((s) => s.terminate()),
      refuseConnections: (on) => void (refuse = on),
      delayReplies: (ms) => void (delay = ms),
      freeze: (on) => {
        frozen = on;
        sockets.forEach((s) => (on ? s.pause() : s.resume()));
      },
      reportStatus: (level, msg) => sockets.forEach((s) => s.send(encode({ op: "status", level, msg }))),
    },
    close: async () => {
      stops.forEach((stop) => stop());
      sockets.forEach((s) => s.terminate());
      await Promise.all([new Promise<void>((resolve) => server.close(() => resolve())), ssh?.close()]);
    },
  };
  server.on("connection", (socket) => {
    const id = String(next++);
    sockets.add(socket);
    if (frozen) socket.pause();
    const send = (text: string) => (delay ? setTimeout(() => socket.send(text), delay) : socket.send(text));
    const connection = new Connection(id, graph, {
      send,
      log: (text) => sim.log.push({ at: at(), connection: id, text }),
      record: (message) => sim.received.push({ at: at(), connection: id, message }),
      statusFrames: options.statusFrames,
    });
    // A binary frame is read as UTF-8 text (the real server happened to
    // answer a binary JSON frame too; see transcript 07).
    socket.on("message", (data) => connection.receive(data.toString()));
    socket.on("close", () => {
      sockets.delete(socket);
      connection.close();
    });
    socket.on("error", () => socket.terminate());
  });
  return sim;
}
