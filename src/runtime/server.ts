// The trial runtime's WebSocket server (Bun). Every message is parsed against
// the socket messages (src/core/socket/messages.ts) and decided against the
// socket's access, which the runtime keeps fresh from the database: loaded at hello, reloaded whenever
// PostgreSQL announces a change (see access.ts), never trusted from the client.
import { oneAfterAnother } from "@/core/one-after-another";
import { arrivalOrder, type Turn } from "@/core/arrival-order";
import { askedAt } from "@/core/trial/freshness";
import {
  annotateVerdict,
  cameraVerdict,
  codeVerdict,
  commandVerdict,
  lostAccess,
  mayReadTrialLog,
  replayVerdict,
  signalVerdict,
  touches,
  type AccessChange,
  type TrialAccess,
} from "@/core/access/trial-socket";
import type { Database } from "@/store/client";
import { verifySocketToken, type SocketClaims } from "@/store/socket-token";
import { haltsTheRobot, type StoredEvent } from "@/core/trial";
import { eventsSince, STATUS_AFTER } from "@/store/event-store";
import {
  parseClientMessage,
  SOCKET_MESSAGES_VERSION,
  toWire,
  type ClientMessage,
  type ServerMessage,
  type Viewer,
} from "@/core/socket/messages";
import { beforeHelloRefusal, LARGEST_FRAME_BYTES, sizeRefusal } from "@/core/socket/limits";
import { partEnds } from "@/core/socket/welcome";
import { Outbox } from "./outbox";
import { loadTrialAccess, spendToken } from "./access";
import { carryOut, TURN_WAIT_MS } from "./carry-out";
import { recordedRobot } from "./robot-status";
import type { CommandForwarding } from "./forwarding";
import type { StopLinks } from "./stop-links";
import type { CommandResult, TrialHost } from "./trial-host";
import { logUnexpected } from "@/store/error-reference";
import type { LiveRobotState } from "@/core/robots/live-state";
import { annotate } from "./annotations";
import { answer, heard, newPulse, type Pulse, watchPulses } from "./heartbeat";
import { helloDoor } from "./hello-door";
import { codeLive } from "./coding";
import type { EventRelay } from "./relay";
import type { Replays } from "./replay";
import type { TrialHosts } from "./trial-hosts";
import type { CameraFrame } from "./robot";
import type { IceServer } from "@/core/network/ice-servers";
import { clientAddress } from "@/core/network/client-address";
import type { IpRange } from "@/core/network/ip";

interface Connection {
  /** Names this connection to the others of its trial, for live video's signals. */
  peerId: string;
  /** Set at the first hello: a connection follows one trial, once. */
  greeted: boolean;
  /** The first hello's work while it is under way (until its welcome is on its way): what the page sends meanwhile waits for it. */
  hello?: Promise<void>;
  closed: boolean;
  claims: SocketClaims | null;
  /** The caller's access now; only set once hello has admitted them. */
  access: TrialAccess | null;
  /** Counts reloads, so an older reload finishing late never overwrites a newer one. */
  reloads: number;
  unsubscribe?: () => void;
  /** Stops the robot's camera frames to this connection (set while it gets them). */
  stopCamera?: () => void;
  /** The host its camera frames come from: the trial's, when this process ran it at hello. */
  cameraHost?: TrialHost;
  /** The page said it does not show the camera (a hidden tab, a closed panel): no frames until it says it does. */
  cameraHidden?: boolean;
  /** Stops this connection's replay, if one is playing. */
  stopReplay?: () => void;
  /** Lets go of the link that stops the robot of a trial another process runs. */
  releaseStop?: () => void;
  /** The connection's replay messages, one after another. */
  replayTurns?: ReturnType<typeof oneAfterAnother>;
  /** Where it comes from: connections that have not said hello are counted per address. */
  address: string;
  /** Until hello: takes it off its address's count of waiting connections, and stops its deadline. */
  leaveDoor?: () => void;
  /** Its heartbeat: when it was last heard, and its page's clock offset (`pulse.clock`) for the command path. */
  pulse: Pulse;
  /** Every message to it, in order (set as it opens). */
  outbox?: Outbox;
}

type Socket = {
  data: Connection;
  send(text: string): number;
  close(code?: number, reason?: string): void;
  /** Bytes queued to this browser and not yet sent (Bun's ServerWebSocket). */
  getBufferedAmount(): number;
};

export interface RuntimeOptions {
  db: Database;
  hosts: TrialHosts;
  relay: EventRelay;
  replays: Replays;
  /** Stops from here the robots of trials other processes run. */
  stops: StopLinks;
  /** Commands of trials other processes run, to their owners. */
  forwarding: CommandForwarding;
  secret: string;
  hostname: string;
  port: number;
  /** STUN/TURN servers the browsers use for live video (HRI_ICE_SERVERS). */
  iceServers?: IceServer[];
  /** Proxies whose X-Forwarded-For is believed (HRI_TRUSTED_PROXIES): limits per address count browsers, not the proxy. */
  trustedProxies?: IpRange[];
}

/** Close codes the browser acts on: 4401 fetch a fresh token and retry; 4403 stop and say why. */
const EXPIRED = 4401;
const SHUT_OUT = 4403;
/** A frame before hello larger than a hello (RFC 6455's "message too big"): the browser reconnects after it. */
const TOO_BIG = 1009;
/** A page that stopped pinging: the browser reconnects after it, if it is still there. */
const GONE_SILENT = 4408;
/** A page too far behind the trial ("try again later"): the browser reconnects and catches up from the log. */
const FELL_BEHIND = 1013;

/** Events written into a welcome's text at a time: a few milliseconds of work each. */
const WELCOME_PAGE = 2000;

const turn = () => new Promise((next) => setImmediate(next));
/**
 * A message's text with its empty events replaced by events' texts, each written once: the first `"events":[]`,
 * as "events" comes before any name.
 */
const withEvents = (text: string, events: string[]) =>
  text.replace('"events":[]', () => `"events":[${events.join(",")}]`);

/**
 * Each event's text, a page at a time, and where the welcome's parts end
 * (src/core/socket/welcome.ts): a long trial's log is written without holding
 * the event loop from the other trials' clients.
 */
async function welcomeParts(events: StoredEvent[]): Promise<{ texts: string[]; ends: number[] }> {
  const texts: string[] = [];
  const sizes: number[] = [];
  for (let start = 0; start < events.length; start += WELCOME_PAGE) {
    if (start) await turn();
    for (const event of events.slice(start, start + WELCOME_PAGE)) {
      const text = JSON.stringify(toWire(event));
      texts.push(text);
      sizes.push(Buffer.byteLength(text));
    }
  }
  return { texts, ends: partEnds(sizes) };
}

// Every client of a trial gets the same batch: serialise it once, not once per client.
const serialised = new WeakMap<StoredEvent[], string>();
function eventsMessage(events: StoredEvent[]): string {
  let text = serialised.get(events);
  if (text === undefined)
    serialised.set(
      events,
      (text = JSON.stringify({ type: "events", events: events.map(toWire) } satisfies ServerMessage)),
    );
  return text;
}

/** A connection this far behind skips the robot's camera frames until it catches up: the frames wait for no one. */
const CAMERA_BACKLOG_BYTES = 256 * 1024;
const cameraMessages = new WeakMap<CameraFrame, string>();
function cameraMessage(frame: CameraFrame): string {
  let text = cameraMessages.get(frame);
  if (text === undefined)
    cameraMessages.set(frame, (text = JSON.stringify({ type: "camera", ...frame } satisfies ServerMessage)));
  return text;
}

const mayRun = (access: TrialAccess) => commandVerdict(access, "next").allow;

export function startRuntimeServer({
  db,
  hosts,
  relay,
  replays,
  stops,
  forwarding,
  secret,
  hostname,
  port,
  iceServers = [],
  trustedProxies = [],
}: RuntimeOptions) {
  /** Admitted sockets by trial: presence, annotations and access changes reach them. */
  const viewers = new Map<string, Set<Socket>>();
  const send = (ws: Socket, message: ServerMessage): void => ws.data.outbox!.send(JSON.stringify(message));
  /** A trial's sockets whose people may read its log now. */
  const readersOf = (trialId: string) =>
    [...(viewers.get(trialId) ?? [])].filter((s) => mayReadTrialLog(s.data.access!));
  /** One message to many sockets: serialised once, not once per socket (a robot's state goes to a whole trial, many times a second). */
  const sendAll = (sockets: Iterable<Socket>, message: ServerMessage): void => {
    const text = JSON.stringify(message);
    for (const s of sockets) s.data.outbox!.send(text);
  };
  const presence = (trialId: string) => {
    const sockets = [...(viewers.get(trialId) ?? [])];
    const list: Viewer[] = sockets.map((s) => ({
      userId: s.data.access!.userId,
      name: s.data.access!.name,
      role: s.data.access!.studyRole ?? "",
      peerId: s.data.peerId,
    }));
    sendAll(sockets, { type: "presence", viewers: list });
    return list;
  };

  const door = helloDoor();
  /** Each trial's commands, in the order they came on this process's sockets. */
  const turnOf = arrivalOrder(TURN_WAIT_MS);

  /** Drops everything the socket held, at once, whoever closes it. */
  function release(ws: Socket) {
    ws.data.leaveDoor?.();
    if (ws.data.closed) return;
    ws.data.closed = true;
    ws.data.unsubscribe?.();
    ws.data.stopCamera?.();
    ws.data.cameraHost = undefined;
    ws.data.stopReplay?.();
    ws.data.releaseStop?.();
    ws.data.outbox?.close();
    const trialId = ws.data.claims?.trialId;
    if (trialId && viewers.get(trialId)?.delete(ws)) presence(trialId);
  }
  const shut = (ws: Socket, code: number, reason: string) => {
    release(ws);
    ws.close(code, reason);
  };

  async function hello(ws: Socket, token: string, lastSeq: number): Promise<void> {
    if (ws.data.greeted) {
      return send(ws, {
        type: "rejected",
        requestId: null,
        reason: "This connection has already said hello: open a new connection to follow another trial.",
      });
    }
    ws.data.greeted = true;
    ws.data.leaveDoor?.();
    const claims = verifySocketToken(token, secret);
    if (!claims) return shut(ws, EXPIRED, "Your link to this trial has expired. Reload the page.");
    if (!(await spendToken(db, claims)))
      return shut(ws, EXPIRED, "This link to the trial was already used. Reload the page.");
    const access = await loadTrialAccess(db, claims.trialId, claims.userId);
    const lost = access ? lostAccess(access) : "This trial no longer exists.";
    if (lost || !access) return shut(ws, SHUT_OUT, lost ?? "");
    if (ws.data.closed) return;
    ws.data.claims = claims;
    ws.data.access = access;
    const trialId = claims.trialId;
    // Admitted: from here on, access changes reach this socket (and may close it).
    viewers.set(trialId, (viewers.get(trialId) ?? new Set()).add(ws));
    const host = await hosts.get(trialId);
    if (ws.data.closed) return;
    // Run by another process: a wizard's stop must reach the robot from here too, with nothing to read first.
    if (!host && mayRun(access)) ws.data.releaseStop = stops.hold(trialId);
    // Until the welcome is sent, what the trial logs meanwhile waits, in order, behind it.
    let held: StoredEvent[][] | null = [];
    // The last seq this page has: each event reaches it once, in order. A batch committed before the log's
    // read may be given out by the host after the welcome (the two answers come on different connections):
    // what the read had is not sent again (found by CI: an observer got seq 2,569 twice).
    let given = lastSeq;
    // Who may run the trial gets a batch at once (its ack follows it); the others a turn later, so a
    // trial's many observers never stand between the wizard and the ack.
    const deliver = (batch: StoredEvent[]) => {
      const now = ws.data.access!;
      // The host's batch itself when all of it is new: its text is then made once for all its pages.
      const events = (batch[0]?.seq ?? 0) > given ? batch : batch.filter((e) => e.seq > given);
      if (events.length) given = events.at(-1)!.seq;
      if (events.length && mayReadTrialLog(now)) {
        if (mayRun(now)) ws.data.outbox!.send(eventsMessage(events));
        else ws.data.outbox!.later(eventsMessage(events));
      }
      // Follow the trial's status, so a log that becomes results stops flowing.
      const status = events.reduce((s, e) => STATUS_AFTER[e.type] ?? s, now.trial.status);
      if (status !== now.trial.status) ws.data.access = { ...now, trial: { ...now.trial, status } };
    };
    let seen = lastSeq;
    const push = (events: StoredEvent[]) => {
      seen = Math.max(seen, events.at(-1)?.seq ?? seen);
      if (held) held.push(events);
      else deliver(events);
    };
    // Owned here: straight from the host, until it closes (another process took the trial over, or it
    // ended): then, as from the start when another process owns it, through the relay.
    const follow = () => {
      if (ws.data.closed) return;
      ws.data.unsubscribe = relay.follow(trialId, seen, push);
      if (mayRun(ws.data.access!)) ws.data.releaseStop ??= stops.hold(trialId);
    };
    // Just opened for this hello: the log the host read to open it, kept up to date (one read, not two).
    // Else the log is read here, after subscribing: what the host gives out during the read is held, and
    // what the read has too dropped from it. Subscribed after the read, an event committed after the
    // read's snapshot but given out before the subscription reached this page never (found by CI).
    const opening = host?.takeOpeningLog(lastSeq);
    if (host) ws.data.unsubscribe = host.subscribe(push, follow);
    const log = opening ?? (await eventsSince(db, trialId, lastSeq));
    if (ws.data.closed) return;
    const logged = log.at(-1)?.seq ?? lastSeq;
    seen = Math.max(seen, logged);
    given = logged;
    // The relay reads what committed between the read and this subscription itself.
    if (!host) ws.data.unsubscribe = relay.follow(trialId, seen, push);
    const shown = mayReadTrialLog(ws.data.access) ? log : [];
    const { texts, ends } = await welcomeParts(shown);
    if (ws.data.closed) return;
    const parts: string[] = [];
    for (const [part, end] of ends.slice(0, -1).entries()) {
      if (part) await turn();
      const empty = JSON.stringify({ type: "welcome.part", part, events: [] } satisfies ServerMessage);
      parts.push(withEvents(empty, texts.slice(ends[part - 1] ?? 0, end)));
    }
    if (ws.data.closed) return;
    const now = ws.data.access;
    const welcome = JSON.stringify({
      type: "welcome",
      version: SOCKET_MESSAGES_VERSION,
      trialId,
      role: now.studyRole!,
      mayRun: mayRun(now),
      events: [],
      parts: parts.length,
      viewers: presence(trialId),
      peerId: ws.data.peerId,
      iceServers,
    } satisfies ServerMessage);
    ws.data.outbox!.parts([...parts, withEvents(welcome, texts.slice(ends.at(-2) ?? 0))]);
    for (const events of held) deliver(events);
    held = null;
    if (!host) {
      // Run by another process: its robot as the owner last recorded it; changes come as the owner says them.
      const robot = await recordedRobot(db, trialId);
      if (robot && !ws.data.closed) send(ws, { type: "robot", connected: robot.connected, name: robot.name });
    }
    if (host) {
      send(ws, { type: "robot", connected: host.robotStatus(), ...(host.robotName ? { name: host.robotName } : {}) });
      if (mayReadTrialLog(ws.data.access!)) send(ws, { type: "robotState", ...host.robotState });
      ws.data.cameraHost = host;
      showCamera(ws);
    }
  }

  /** The robot's camera, to whoever may follow the trial now and shows it, as fast as their connection takes it. */
  function showCamera(ws: Socket) {
    const host = ws.data.cameraHost;
    if (!host || ws.data.stopCamera || ws.data.cameraHidden || ws.data.closed) return;
    ws.data.stopCamera = host.watchCamera((frame) => {
      if (ws.data.closed || !mayReadTrialLog(ws.data.access!)) return;
      if (ws.data.outbox!.idle && ws.getBufferedAmount() < CAMERA_BACKLOG_BYTES)
        ws.data.outbox!.send(cameraMessage(frame));
    });
  }

  /** The page shows the robot's camera now, or not: the frames start or stop (the robot's with the last watcher). */
  function camera(ws: Socket, message: Extract<ClientMessage, { type: "camera" }>) {
    const { claims, access } = ws.data;
    const reject = (reason: string) => send(ws, { type: "rejected", requestId: message.requestId, reason });
    if (!claims || !access) return reject("Say hello with your trial link first.");
    const verdict = cameraVerdict(access, message.watch);
    if (!verdict.allow) return reject(verdict.reason);
    ws.data.cameraHidden = !message.watch;
    if (message.watch) showCamera(ws);
    else {
      ws.data.stopCamera?.();
      ws.data.stopCamera = undefined;
    }
    send(ws, { type: "ack", requestId: message.requestId, seqs: [] });
  }

  /** Reloads one socket's access; closes it if its user may no longer be here. */
  async function recheck(ws: Socket) {
    const { claims } = ws.data;
    if (!claims || ws.data.closed) return;
    const reload = ++ws.data.reloads;
    const access = await loadTrialAccess(db, claims.trialId, claims.userId);
    if (reload !== ws.data.reloads || ws.data.closed) return;
    const lost = access ? lostAccess(access) : "This trial no longer exists.";
    if (lost || !access) return shut(ws, SHUT_OUT, lost ?? "");
    const before = ws.data.access!;
    ws.data.access = access;
    // A replay is for those who may read the trial's analysis: one who no longer may, stops seeing it.
    if (ws.data.stopReplay && !replayVerdict(access).allow) {
      ws.data.stopReplay();
      ws.data.stopReplay = undefined;
    }
    if (before.studyRole !== access.studyRole || mayRun(before) !== mayRun(access)) {
      send(ws, { type: "access", role: access.studyRole!, mayRun: mayRun(access) });
    }
    if (before.studyRole !== access.studyRole) presence(claims.trialId);
  }

  const admitted = () => [...viewers.values()].flatMap((set) => [...set]);
  watchPulses(() =>
    admitted().map((ws) => ({
      pulse: ws.data.pulse,
      send: (message) => send(ws, message),
      drop: (reason) => shut(ws, GONE_SILENT, reason),
    })),
  );
  /** A change PostgreSQL announced: reload the access of the sockets it concerns, at once. */
  const accessChanged = (change: AccessChange) => {
    for (const ws of admitted()) {
      const access = ws.data.access!;
      if (touches(change, { userId: access.userId, studyId: access.studyId, trialId: ws.data.claims!.trialId }))
        void recheck(ws).catch(logError);
    }
  };
  /** After the listening connection was down: anything may have changed. */
  const recheckAll = () => {
    for (const ws of admitted()) void recheck(ws).catch(logError);
  };

  /** Tells everyone in a trial at once when its robot drops or comes back. */
  const announceRobot = (trialId: string, connected: boolean, detail?: string) => {
    sendAll(viewers.get(trialId) ?? [], { type: "robot", connected, ...(detail ? { detail } : {}) });
  };

  /** Tells those in a trial who may read its log what its robot is doing now (what it says is the log's business). */
  const announceRobotState = (trialId: string, state: LiveRobotState) => {
    sendAll(readersOf(trialId), { type: "robotState", ...state });
  };

  async function act(ws: Socket, message: Extract<ClientMessage, { type: "command" | "annotate" }>): Promise<void> {
    const { claims, access } = ws.data;
    if (!claims || !access)
      return send(ws, {
        type: "rejected",
        requestId: message.requestId,
        reason: "Say hello with your trial link first.",
      });
    const reject = (reason: string) => send(ws, { type: "rejected", requestId: message.requestId, reason });
    // Decided against the access as it is now: no database round trip here.
    const verdict = message.type === "command" ? commandVerdict(access, message.command.kind) : annotateVerdict(access);
    if (!verdict.allow) return reject(verdict.reason);
    if (message.type === "annotate") {
      const annotation = await annotate(
        db,
        { trialId: claims.trialId, userId: access.userId, name: access.name },
        message.label,
        message.note,
      );
      sendAll(readersOf(claims.trialId), { type: "annotation", annotation });
      return send(ws, { type: "ack", requestId: message.requestId, seqs: [] });
    }
    // When the wizard asked, on this process's clock, from the page's time and the connection's offset.
    const asked = askedAt(message.at, ws.data.pulse.clock?.offsetMs ?? null, Date.now());
    if (!asked.ok) return reject(asked.reason);
    // Taken before anything is awaited: the trial's commands reach its queue in the order they came.
    const turn = turnOf(claims.trialId);
    try {
      await carry(ws, message, claims.trialId, access, verdict.claim, asked.at, turn);
    } finally {
      turn.done();
    }
  }

  /** A wizard's command, in its turn: to its host here, or to the process that runs the trial. */
  async function carry(
    ws: Socket,
    message: Extract<ClientMessage, { type: "command" }>,
    trialId: string,
    access: TrialAccess,
    claim: boolean,
    at: number,
    turn: Turn,
  ): Promise<void> {
    const reject = (reason: string) => send(ws, { type: "rejected", requestId: message.requestId, reason });
    const host = await hosts.get(trialId);
    const halting = haltsTheRobot(message.command.kind);
    let halted = false;
    const tellHalted = () => {
      if (halted) return;
      halted = true;
      send(ws, { type: "halted", requestId: message.requestId });
    };
    let result: CommandResult & { claimed?: boolean };
    if (host) result = await carryOut(db, host, trialId, access, message, claim, tellHalted, at, turn);
    else {
      // Run by another process: a stop goes to the robot from here too, never waiting on the database.
      if (halting && !message.retry && stops.halt(trialId)) tellHalted();
      if (!halting) await turn.wait();
      // Handed on in turn: the forwarding keeps the order from here (forwarding.ts).
      const forwarded = forwarding.forward({
        trialId,
        userId: access.userId,
        requestId: message.requestId,
        retry: message.retry,
        command: message.command,
        askedAt: at,
      });
      turn.done();
      const answer = await forwarded;
      // No process answered: its owner is gone, and this one takes the trial over.
      const taken = answer ? null : await hosts.get(trialId);
      if (taken) result = await carryOut(db, taken, trialId, access, message, claim, tellHalted, at, turnOf(trialId));
      else if (!answer)
        return reject(
          "The runtime process running this trial did not answer in time: the trial's log shows whether this was done.",
        );
      else {
        if (answer.halted) tellHalted();
        result = answer;
      }
    }
    if (result.claimed)
      ws.data.access = { ...ws.data.access!, trial: { ...ws.data.access!.trial, wizardId: access.userId } };
    if (result.ok) send(ws, { type: "ack", requestId: message.requestId, seqs: result.seqs });
    else reject(result.reason);
  }

  /** Starts or stops this connection's replay of its (finished) trial on the simulated robot. */
  async function replay(
    ws: Socket,
    message: Extract<ClientMessage, { type: "replay" | "replay_stop" }>,
  ): Promise<void> {
    const { claims, access } = ws.data;
    const reject = (reason: string) => send(ws, { type: "rejected", requestId: message.requestId, reason });
    if (!claims || !access) return reject("Say hello with your trial link first.");
    const verdict = replayVerdict(access);
    if (!verdict.allow) return reject(verdict.reason);
    ws.data.stopReplay?.();
    ws.data.stopReplay = undefined;
    if (message.type === "replay") {
      const started = await replays.play(claims.trialId, message, (status) => {
        if (!ws.data.closed) send(ws, status);
      });
      if (!started.ok) return reject(started.reason);
      // Closed while it was starting: the replay goes with the connection.
      if (ws.data.closed) return started.stop();
      ws.data.stopReplay = started.stop;
    }
    send(ws, { type: "ack", requestId: message.requestId, seqs: [] });
  }

  /**
   * Passes a live video signal to another connection of the same trial, as it is. Never
   * touches the database or the trial's host: video can neither delay nor block a command.
   */
  function signal(ws: Socket, message: Extract<ClientMessage, { type: "signal" }>) {
    const { claims, access } = ws.data;
    const reject = (reason: string) => send(ws, { type: "rejected", requestId: message.requestId, reason });
    if (!claims || !access) return reject("Say hello with your trial link first.");
    // Looked up among this trial's own connections: a peer of any other trial is not found.
    const to = [...(viewers.get(claims.trialId) ?? [])].find((s) => s.data.peerId === message.peerId && s !== ws);
    if (!to) return reject("That person is no longer connected to this trial: the video to them was not sent.");
    const verdict = signalVerdict(access, to.data.access!);
    if (!verdict.allow) return reject(verdict.reason);
    send(to, { type: "signal", peerId: ws.data.peerId, signal: message.signal });
    send(ws, { type: "ack", requestId: message.requestId, seqs: [] });
  }

  async function onMessage(ws: Socket, text: string, bytes: number): Promise<void> {
    if (ws.data.closed) return;
    heard(ws.data.pulse);
    // Before hello, a frame larger than a hello is not even read.
    const unasked = ws.data.greeted ? null : beforeHelloRefusal(bytes);
    if (unasked) return shut(ws, TOO_BIG, unasked);
    const parsed = parseClientMessage(text);
    if (!parsed.ok) return send(ws, { type: "rejected", requestId: null, reason: parsed.reason });
    const message = parsed.message;
    const tooLarge = sizeRefusal(message.type, bytes);
    if (tooLarge)
      return send(ws, {
        type: "rejected",
        requestId: "requestId" in message ? message.requestId : null,
        reason: tooLarge,
      });
    if (message.type === "ping") return send(ws, answer(ws.data.pulse, message));
    if (message.type === "hello") {
      // A hello that fails half way must not leave a connection that follows nothing.
      const said = hello(ws, message.token, message.lastSeq).catch((error: unknown) => {
        const ref = logUnexpected(error, "trial socket hello");
        shut(ws, 1011, `The server could not open this trial (reference ${ref}). Reload the page.`);
      });
      if (!ws.data.hello) {
        ws.data.hello = said;
        // Done, it is forgotten: what comes later goes straight on (those waiting for it resume first, in order).
        void said.finally(() => (ws.data.hello = undefined));
      }
      return said;
    }
    // Sent right behind the hello, before its welcome (a key pressed as the page opens): taken, in the order
    // sent, once the hello is done, rather than refused as if no hello had been said.
    if (ws.data.hello) await ws.data.hello;
    if (ws.data.closed) return;
    if (message.type === "signal") return signal(ws, message);
    if (message.type === "replay" || message.type === "replay_stop") {
      // One at a time: a quick run of seeks ends with the last one playing, and held by this connection.
      ws.data.replayTurns ??= oneAfterAnother();
      return ws.data.replayTurns(() => replay(ws, message));
    }
    if (message.type === "code") return code(ws, message);
    if (message.type === "camera") return camera(ws, message);
    return act(ws, message);
  }

  /** An observer's key press: answered to them alone, with the changes to their own tier. */
  async function code(ws: Socket, message: Extract<ClientMessage, { type: "code" }>): Promise<void> {
    const { claims, access } = ws.data;
    const reject = (reason: string) => send(ws, { type: "rejected", requestId: message.requestId, reason });
    if (!claims || !access) return reject("Say hello with your trial link first.");
    const verdict = codeVerdict(access);
    if (!verdict.allow) return reject(verdict.reason);
    const coded = await codeLive(db, { trialId: claims.trialId, observerId: access.userId }, message);
    if (!coded.ok) return reject(coded.reason);
    send(ws, { type: "codes", requestId: message.requestId, codes: coded.changed });
    send(ws, { type: "ack", requestId: message.requestId, seqs: [] });
  }

  const server = Bun.serve<Connection>({
    hostname,
    port,
    fetch(req, server) {
      if (
        server.upgrade(req, {
          data: {
            peerId: crypto.randomUUID(),
            greeted: false,
            closed: false,
            claims: null,
            access: null,
            reloads: 0,
            pulse: newPulse(),
            address: clientAddress({
              socketAddress: server.requestIP(req)?.address,
              forwardedFor: req.headers.get("x-forwarded-for") ?? undefined,
              trustedProxies,
            }),
          },
        })
      )
        return undefined;
      return new Response("This is the HRIStudio trial runtime: connect with a WebSocket.", { status: 426 });
    },
    websocket: {
      // Bun reads a whole frame before handing it over: nothing larger than the largest message is read.
      maxPayloadLength: LARGEST_FRAME_BYTES,
      open(ws) {
        ws.data.outbox = new Outbox(
          (text) => ws.send(text),
          () => shut(ws, FELL_BEHIND, "This page fell too far behind the trial: it reconnects and catches up."),
        );
        ws.data.leaveDoor = door.enter(ws.data.address, (code, reason) => shut(ws, code, reason)) ?? undefined;
      },
      async message(ws, raw): Promise<void> {
        const text = typeof raw === "string" ? raw : new TextDecoder().decode(raw);
        try {
          await onMessage(ws, text, typeof raw === "string" ? Buffer.byteLength(raw) : raw.byteLength);
        } catch (error) {
          // One failed message must never take the trial down for everyone else.
          const ref = logUnexpected(error, "trial socket message");
          const requestId = (JSON.parse(text) as { requestId?: string }).requestId ?? null;
          send(ws, {
            type: "rejected",
            requestId,
            reason: `The server could not store that; nothing was changed. Try again (reference ${ref}).`,
          });
        }
      },
      // The browser's buffer has room again: what waits for it goes on.
      drain(ws) {
        ws.data.outbox?.drain();
      },
      close(ws) {
        release(ws);
      },
    },
  });
  return { server, announceRobot, announceRobotState, accessChanged, recheckAll };
}

function logError(error: unknown) {
  logUnexpected(error, "trial runtime");
}
