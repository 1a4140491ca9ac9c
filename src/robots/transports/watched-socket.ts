// roslib's socket to rosbridge, with the liveness roslib lacks. Liveness is
// WebSocket ping/pong: every WebSocket server answers a ping at the protocol
// level (autobahn, tornado, ws), so no rosbridge op is needed, no rosapi, and
// nothing is written to the bridge's log. A bridge whose process is stopped
// keeps its socket open but answers no ping: after `timeoutMs` without a pong
// the socket is terminated (no close handshake, which a stopped peer would
// never finish) and the loss is told at once.
//
// Pongs come back in the order pings went out, after everything sent before
// them was read by the server. So `delivered()` (a ping after a send, and its
// pong) proves the bridge took the frame in; a frame whose pong never comes
// may be lost, and the action is failed rather than called completed.
import { createRequire } from "node:module";
import { dirname, join } from "node:path";
import { AbstractTransport } from "roslib";
import { WebSocket as WsClient } from "ws";
import { linkProblem } from "../../core/robots/link-problem";
import { parsePythonJson } from "../../core/robots/python-json";

/**
 * The `ws` client itself, under Bun too: Bun answers `import "ws"` with a native client of its own that
 * keeps no raw socket, so a lost link could only be closed, never reset (see `terminate`). The package's
 * own client, loaded by its path, runs on Bun's node:net, whose sockets reset.
 */
function wsClient(): typeof WsClient {
  if (!process.versions.bun) return WsClient;
  const require = createRequire(import.meta.url);
  return require(join(dirname(require.resolve("ws/package.json")), "lib", "websocket.js"));
}
const WebSocket = wsClient();

export interface Liveness {
  /** How often a ping goes out, in ms. */
  everyMs: number;
  /** A ping unanswered this long means the bridge is gone. */
  timeoutMs: number;
}

export class WatchedSocket extends AbstractTransport {
  private readonly socket: WsClient;
  private pinged = 0;
  private ponged = 0;
  /** When each unanswered ping went out, oldest first. */
  private readonly unanswered: number[] = [];
  private readonly waiting = new Map<number, Set<(answered: boolean) => void>>();
  private timer: NodeJS.Timeout | null = null;
  private lostReason: string | null = null;
  /** The last round trip of a ping, in ms. */
  lastRoundTripMs: number | null = null;

  constructor(
    url: string,
    private readonly liveness: Liveness,
    /** Told once, when the socket is given up or closes by itself. */
    private readonly onLost: (reason: string) => void,
  ) {
    super();
    // A host that takes the connection and never answers is given up like one that stops answering pings.
    this.socket = new WebSocket(url, { perMessageDeflate: false, handshakeTimeout: liveness.timeoutMs });
    this.socket.binaryType = "arraybuffer";
    this.socket.on("open", () => {
      this.emit("open", undefined);
      this.timer = setInterval(() => this.beat(), liveness.everyMs);
    });
    this.socket.on("pong", () => this.answered());
    this.socket.on("message", (data, isBinary) =>
      this.handleRawMessage(isBinary ? data : this.parsed(data.toString())),
    );
    this.socket.on("close", (code) => {
      this.lose(`the robot's bridge closed the connection (code ${code})`);
      this.emit("close", code);
    });
    this.socket.on("error", (error) => {
      this.emit("error", error);
      this.lose(`the robot's bridge cannot be reached: ${linkProblem(error)}`);
    });
  }

  /** A bridge may write NaN and Infinity as Python's bare literals (rosbridge writes null); roslib's JSON.parse would drop the whole message. */
  private parsed(text: string): unknown {
    try {
      return parsePythonJson(text);
    } catch {
      return text; // roslib reports what does not parse
    }
  }

  send(message: unknown) {
    if (this.isOpen()) this.socket.send(JSON.stringify(message));
  }

  close() {
    this.terminate("the connection was closed");
  }

  /**
   * Drops the socket at once, without waiting for the peer, and resets it where the platform lets us: a
   * TCP reset (SO_LINGER 0, Node's `resetAndDestroy`) throws away what our side still queues for the
   * bridge, where a polite close (FIN) would deliver it late to a bridge that goes on. What already
   * reached the bridge's machine is out of our hands: it is reported "sent, outcome unknown".
   */
  terminate(reason: string) {
    this.lose(reason);
    const raw = (this.socket as unknown as { _socket?: { resetAndDestroy?: () => void } })._socket;
    if (typeof raw?.resetAndDestroy === "function") raw.resetAndDestroy();
    this.socket.terminate();
  }

  /** Resolves true once the bridge has read everything sent so far; false if the link is lost first. */
  delivered(): Promise<boolean> {
    if (!this.isOpen()) return Promise.resolve(false);
    const ticket = this.ping();
    return new Promise((resolve) => {
      const set = this.waiting.get(ticket) ?? new Set();
      this.waiting.set(ticket, set.add(resolve));
    });
  }

  isConnecting = () => this.socket.readyState === WebSocket.CONNECTING;
  isOpen = () => this.socket.readyState === WebSocket.OPEN && this.lostReason === null;
  isClosing = () => this.socket.readyState === WebSocket.CLOSING;
  isClosed = () => this.socket.readyState === WebSocket.CLOSED || this.lostReason !== null;

  private beat() {
    const oldest = this.unanswered[0];
    if (oldest !== undefined && Date.now() - oldest >= this.liveness.timeoutMs)
      return this.terminate(`the robot's bridge stopped answering (no reply for ${this.liveness.timeoutMs} ms)`);
    this.ping();
  }

  private ping(): number {
    this.unanswered.push(Date.now());
    this.socket.ping();
    return ++this.pinged;
  }

  private answered() {
    const sent = this.unanswered.shift();
    if (sent !== undefined) this.lastRoundTripMs = Date.now() - sent;
    this.ponged++;
    const wake = this.waiting.get(this.ponged);
    this.waiting.delete(this.ponged);
    wake?.forEach((resolve) => resolve(true));
  }

  private lose(reason: string) {
    if (this.lostReason !== null) return;
    this.lostReason = reason;
    if (this.timer) clearInterval(this.timer);
    for (const wake of this.waiting.values()) wake.forEach((resolve) => resolve(false));
    this.waiting.clear();
    this.onLost(reason);
  }
}
