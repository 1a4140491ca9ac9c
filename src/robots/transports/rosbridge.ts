// The rosbridge v2 transport, through the real roslib client. rosbridge
// acknowledges nothing and reports most errors only in its own log, so:
// - a topic publish is "completed" only once the bridge has read it (a
//   WebSocket ping sent after it was answered: see watched-socket.ts);
//   one whose answer never comes is "sent, outcome unknown" (the bridge may
//   still read it once it goes on), never "completed" nor "failed";
// - nothing is sent past the action's freshness (`freshUntil`): a retryable
//   action waits for a lost link only until then, and is "not sent" after;
// - a lost link is reset (watched-socket.ts), not closed politely, so what
//   is still queued to the bridge is thrown away rather than delivered late;
// - a service call completes or fails on its service_response, or times out,
//   and fails at once if the link is lost while it waits;
// - liveness is WebSocket ping/pong (every rosbridge answers it, nothing is
//   logged): a bridge that stops answering is given up within
//   heartbeatTimeoutMs + heartbeatEveryMs, its socket terminated;
// - a `status` frame of level error or warning (servers that send them) is
//   told to the trial as the robot's problem;
// - a subscribed topic that stays silent past its expected rate, or whose
//   subscription the bridge refused, is told in plain words (topic-silence.ts):
//   a ROS 1 bridge refuses ROS 2 type names and says so only in its log.
// Server state belongs to one connection (transcript 09): after every
// reconnect a fresh roslib.Ros is made and state subscriptions are re-sent.
import * as ROSLIB from "roslib";
import {
  completionOf,
  estimatedMs,
  expectedDone,
  outgoingFor,
  robotTimeOf,
  serviceRefusal,
  sentOverRos,
  type Confirmation,
  type JsonValue,
  type Outgoing,
  type Plugin,
  type PluginAction,
} from "../../core/plugins";
import { linkProblem } from "../../core/robots/link-problem";
import { refusalOf, refusedAdvertise, type WatchedTopic } from "../../core/robots/silent-topics";
import { DoneTopics } from "./done-topics";
import {
  addressProblem,
  backoffDelay,
  checkedParameters,
  LinkedTransport,
  RECONNECT_BACKOFF,
  timeoutOf,
  unreached,
  type Backoff,
} from "./link";
import { holdThenStop, readOnce, sendGoal } from "./ros2-goal";
import { TopicSilence } from "./topic-silence";
import type { DispatchOptions, DispatchOutcome } from "./transport";
import { WatchedSocket } from "./watched-socket";

/** How long after a lost link an action's done message is still listened for, and told as the robot's later word. */
const LATER_REPORT_MS = 60_000;

export interface RosbridgeOptions {
  url: string;
  heartbeatEveryMs?: number;
  heartbeatTimeoutMs?: number;
  /** Reconnect delays grow from the first to the last (default: RECONNECT_BACKOFF). */
  backoffMs?: Backoff;
  /** The robot's plugin, for what an action needs of the robot as a whole (its top turning speed). */
  plugin?: Pick<Plugin, "actions">;
  /** A topic is called silent after at least this long with nothing (default SILENT_FLOOR_MS). */
  silentFloorMs?: number;
}

interface StateSubscription {
  topic: string;
  messageType: string;
  throttleRate: number;
  kind: WatchedTopic["kind"];
  onMessage: (message: unknown) => void;
  /** The roslib topic on the live connection, and what it calls there. */
  current?: ROSLIB.Topic;
  heard?: (message: unknown) => void;
}

export class RosbridgeTransport extends LinkedTransport {
  private ros: ROSLIB.Ros | null = null;
  private topics = new Map<string, ROSLIB.Topic>();
  private readonly subscriptions = new Set<StateSubscription>();
  private timers = new Set<NodeJS.Timeout>();
  private socket: WatchedSocket | null = null;
  private readonly done = new DoneTopics((topic, messageType, onMessage) =>
    this.watch({ topic, messageType, onMessage, throttleRate: 0, kind: "completion" }),
  );
  private waiting = new Set<() => void>();
  private readonly silence: TopicSilence;

  constructor(private readonly options: RosbridgeOptions) {
    super();
    this.silence = new TopicSilence((problem) => this.tell(problem), options.silentFloorMs);
  }

  connect(): Promise<void> {
    if (this.status.state === "closed") return Promise.reject(new Error("transport closed"));
    // No wait mends an address that is not one: the trial's first action is not held for it.
    const address = this.addressProblem();
    if (address) {
      this.setState("disconnected", address);
      return Promise.reject(new Error(address));
    }
    if (this.status.state !== "connected") this.open();
    return this.connectedWithin(Date.now() + 10_000).then((ros) => {
      if (!ros) throw new Error(`cannot reach rosbridge at ${this.options.url}: ${this.lostReason()}`);
    });
  }

  async dispatch(
    action: PluginAction,
    parameters: Record<string, unknown>,
    options: DispatchOptions = {},
  ): Promise<DispatchOutcome> {
    const started = Date.now();
    const freshUntil = options.freshUntil ?? Number.POSITIVE_INFINITY;
    const timeoutMs = timeoutOf(action);
    const checked = checkedParameters(action, parameters);
    if (!checked.ok) return checked.outcome;
    const outgoing = outgoingFor(action, checked.parameters, this.options.plugin);
    options.sending?.(sentOverRos(outgoing));
    if (outgoing.kind === "none") return { status: "failed", reason: outgoing.reason };
    if (outgoing.kind === "ssh")
      return { status: "failed", reason: `action "${action.id}" runs over SSH, not rosbridge` };
    const address = this.addressProblem();
    if (address) return { status: "failed", reason: address };
    const ros =
      this.status.state === "connected"
        ? this.ros
        : action.retryable
          ? await this.connectedWithin(Math.min(started + timeoutMs, freshUntil))
          : null;
    // Waited for the link until the action was too old to send (or got it back too late): never sent late.
    if (ros ? Date.now() > freshUntil : freshUntil < started + timeoutMs)
      return {
        status: "not_sent",
        reason: `Not sent: the robot's link was not back before this was too old to do (${this.lostReason()}).`,
      };
    if (!ros) return unreached(action, started, `robot not connected: ${this.lostReason()}`);
    if (outgoing.kind === "publish")
      return this.published(ros, action, checked.parameters, outgoing, started + timeoutMs, options.later);
    if (outgoing.kind === "goal") return sendGoal(ros, outgoing, started + timeoutMs);
    if (outgoing.kind === "read") return readOnce(ros, outgoing, started + timeoutMs);
    if (outgoing.kind === "motion")
      return holdThenStop((m) => this.publish(outgoing.topic, outgoing.messageType, m), outgoing);
    return this.call(ros, outgoing.service, outgoing.serviceType, outgoing.args, started + timeoutMs);
  }

  /** A topic publish, completed as its rule says: a matching done message, an estimated duration, or only delivered. */
  private async published(
    ros: ROSLIB.Ros,
    action: PluginAction,
    parameters: Record<string, unknown>,
    outgoing: Extract<Outgoing, { kind: "publish" }>,
    deadline: number,
    later?: DispatchOptions["later"],
  ): Promise<DispatchOutcome> {
    const started = Date.now();
    const rule = completionOf(action);
    if (rule.kind === "action_result")
      return {
        status: "failed",
        reason: `"${action.name}" waits for a ROS 2 action result but is sent as a topic message`,
      };
    const expected = rule.kind === "done_topic" ? expectedDone(rule.match, parameters) : null;
    if (expected && !expected.ok) return { status: "failed", reason: expected.reason };
    // Waiting starts before the send, so an answer that comes at once is not missed.
    const done =
      rule.kind === "done_topic" && expected?.ok
        ? this.done.wait(rule.topic, rule.messageType, expected.match, deadline + estimatedMs(rule, parameters))
        : null;
    const socket = this.socket;
    this.topic(ros, outgoing.topic, outgoing.messageType).publish(outgoing.message);
    const detail = (confirmation: Confirmation) => ({ topic: outgoing.topic, confirmation });
    const doneBy = (message: unknown): DispatchOutcome => {
      const robotTime = robotTimeOf(message);
      const source = rule.kind === "done_topic" ? rule.topic : outgoing.topic;
      return {
        status: "completed",
        detail: detail({ by: "done_topic", confirmed: true, source, ...(robotTime ? { robotTime } : {}) }),
      };
    };
    // The link was lost with the action's outcome unknown: its done message, should it come once the link
    // is back (the done topic is subscribed again on every connection), is told as the robot's later word.
    const listenLater = () => {
      if (!later || rule.kind !== "done_topic" || !expected?.ok) return;
      const late = this.done.wait(rule.topic, rule.messageType, expected.match, Date.now() + LATER_REPORT_MS, true);
      void late.answer.then((answer) => typeof answer === "object" && later(doneBy(answer.message)));
    };
    if (!socket || !(await socket.delivered())) {
      done?.cancel();
      listenLater();
      return {
        status: "unknown",
        reason: `sent, but the robot link was lost before the robot's bridge confirmed it took it in (${this.lostReason()}): the robot may still have done it`,
      };
    }
    if (done && rule.kind === "done_topic") {
      const answer = await done.answer;
      if (answer === "timeout") {
        this.silence.waitedOut(rule.topic);
        return { status: "timed_out", afterMs: Date.now() - started };
      }
      if (answer === "lost") {
        listenLater();
        return {
          status: "unknown",
          reason: `the robot took it in, and the link was lost before the robot said it was done (${this.lostReason()}): it may still be done`,
        };
      }
      return doneBy(answer.message);
    }
    if (rule.kind === "estimated_duration") {
      const ms = estimatedMs(rule, parameters);
      if (started + ms > deadline)
        return this.after(deadline - started, { status: "timed_out", afterMs: deadline - started });
      return this.after(ms, { status: "completed", detail: detail({ by: "estimated_duration", confirmed: false }) });
    }
    return { status: "completed", detail: detail({ by: "delivered", confirmed: false }) };
  }

  /** An outcome told after a pause, unless the transport is closed first. */
  private after(ms: number, outcome: DispatchOutcome): Promise<DispatchOutcome> {
    return new Promise((resolve) => {
      const timer = setTimeout(() => {
        this.timers.delete(timer);
        resolve(outcome);
      }, ms);
      this.timers.add(timer);
    });
  }

  /** A message of our own (not a plugin action's) on a topic, if connected now: false if not. */
  publish(topic: string, messageType: string, message: JsonValue): boolean {
    if (this.status.state !== "connected" || !this.ros) return false;
    this.topic(this.ros, topic, messageType).publish(message);
    return true;
  }

  override subscribe(
    topic: string,
    messageType: string,
    onMessage: (message: unknown) => void,
    options: { throttleRate?: number; kind?: "state" | "event" } = {},
  ) {
    const { throttleRate = 0, kind = "state" } = options;
    return this.watch({ topic, messageType, onMessage, throttleRate, kind });
  }

  private watch(subscription: StateSubscription) {
    this.subscriptions.add(subscription);
    if (this.ros && this.status.state === "connected") this.listen(this.ros, subscription);
    return () => {
      this.subscriptions.delete(subscription);
      if (this.status.state === "connected") subscription.current?.unsubscribe(subscription.heard);
      if (![...this.subscriptions].some((s) => s.topic === subscription.topic)) this.silence.forget(subscription.topic);
    };
  }

  async close() {
    this.setState("closed");
    this.timers.forEach(clearTimeout);
    this.silence.stop();
    this.socket?.terminate("the connection was closed");
    this.done.lose(true);
    this.ros = null;
    this.socket = null;
    this.waiting.forEach((wake) => wake());
  }

  private open() {
    const liveness = {
      everyMs: this.options.heartbeatEveryMs ?? 500,
      timeoutMs: this.options.heartbeatTimeoutMs ?? 1500,
    };
    let socket: WatchedSocket | null = null;
    const lost = (reason: string) => {
      if (this.ros !== ros || this.status.state === "closed") return;
      this.ros = null;
      this.socket = null;
      this.silence.reset();
      this.setState("disconnected", reason);
      this.done.lose();
      this.reconnectLater();
    };
    const ros = new ROSLIB.Ros({
      transportFactory: async (url) => {
        socket = new WatchedSocket(url, liveness, lost);
        socket.on("message", (message) => this.bridgeSaid(message as { op?: unknown; level?: unknown; msg?: unknown }));
        this.socket = socket;
        return socket;
      },
    });
    this.ros = ros;
    this.topics = new Map();
    // Why the last try failed stays told while the next one is made.
    this.setState("connecting", this.status.reason);
    ros.on("connection", () => {
      if (this.ros !== ros) return;
      this.status.attempts = 0;
      this.setState("connected");
      this.silence.reset();
      this.subscriptions.forEach((s) => this.listen(ros, s));
      this.waiting.forEach((wake) => wake());
    });
    ros
      .connect(this.options.url)
      .catch((error: unknown) => lost(`cannot reach the robot's bridge at ${this.options.url}: ${linkProblem(error)}`));
  }

  override health() {
    return { ...super.health(), lastHeartbeatMs: this.socket?.lastRoundTripMs ?? this.status.lastHeartbeatMs };
  }

  /**
   * A `status` frame (rosbridge's protocol; the recorded servers never send one): a refused subscription
   * or advertise is told as what the wizard will miss; other errors and warnings as the bridge said them.
   */
  private bridgeSaid(message: { op?: unknown; level?: unknown; msg?: unknown }) {
    if (message.op !== "status" || (message.level !== "error" && message.level !== "warning")) return;
    const refusal = refusalOf(message);
    if (refusal?.op === "subscribe" && this.silence.refused(refusal.topic, refusal.text)) return;
    if (refusal?.op === "advertise") {
      const advertised = [...this.topics.keys()].find((key) => key.startsWith(`${refusal.topic}:`));
      return this.tell(
        refusedAdvertise(refusal.topic, advertised?.slice(refusal.topic.length + 1) ?? null, refusal.text),
      );
    }
    this.tell(
      `the robot's bridge reported ${message.level === "error" ? "an error" : "a warning"}: ${typeof message.msg === "string" ? message.msg : "(no text)"}`,
    );
  }

  // ws takes http(s) addresses too, and some records have them.
  private addressProblem = () =>
    addressProblem("the robot's bridge", this.options.url, ["ws:", "wss:", "http:", "https:"]);

  private lostReason() {
    if (this.status.reason) return this.status.reason;
    return this.status.state === "connecting"
      ? "the link to the robot's bridge is still being opened"
      : "the robot's bridge did not answer";
  }

  private reconnectLater() {
    if (this.status.state === "closed") return;
    const delay = backoffDelay(this.status.attempts++, this.options.backoffMs ?? RECONNECT_BACKOFF);
    const timer = setTimeout(() => {
      this.timers.delete(timer);
      if (this.status.state !== "closed") this.open();
    }, delay);
    this.timers.add(timer);
  }

  private call(
    ros: ROSLIB.Ros,
    name: string,
    serviceType: string,
    args: unknown,
    deadline: number,
  ): Promise<DispatchOutcome> {
    const started = Date.now();
    return new Promise((resolve) => {
      const timer = setTimeout(
        () => resolve({ status: "timed_out", afterMs: Date.now() - started }),
        Math.max(0, deadline - started),
      );
      const done = (outcome: DispatchOutcome) => {
        clearTimeout(timer);
        unwatch();
        resolve(outcome);
      };
      // A lost link will never bring the answer: fail now, with why, rather than at the timeout.
      const unwatch = this.onHealth((health) => {
        if (health.state !== "connected" && !health.problem)
          done({
            status: "unknown",
            reason: `sent, and the robot link was lost while waiting for the answer (${this.lostReason()}): the robot may still have done it`,
          });
      });
      new ROSLIB.Service({ ros, name, serviceType }).callService(
        args,
        (values) => {
          const refused = serviceRefusal(name, values);
          if (refused) return done({ status: "failed", reason: refused });
          done({
            status: "completed",
            detail: {
              response: values as Record<string, unknown>,
              confirmation: { by: "service_response", confirmed: true, source: name } satisfies Confirmation,
            },
          });
        },
        (error) => done({ status: "failed", reason: String(error) }),
      );
    });
  }

  private topic(ros: ROSLIB.Ros, name: string, messageType: string) {
    const key = `${name}:${messageType}`;
    let topic = this.topics.get(key);
    if (!topic) {
      topic = new ROSLIB.Topic({ ros, name, messageType, reconnect_on_close: false });
      this.topics.set(key, topic);
    }
    return topic;
  }

  private listen(ros: ROSLIB.Ros, s: StateSubscription) {
    this.silence.listening(s.topic, s.messageType, s.kind, s.throttleRate);
    s.heard = (message) => {
      this.silence.heard(s.topic);
      s.onMessage(message);
    };
    s.current = new ROSLIB.Topic({
      ros,
      name: s.topic,
      messageType: s.messageType,
      throttle_rate: s.throttleRate,
      // Throttled, the newest message of each interval is kept and sent at its end: without a queue rosbridge
      // sends only one that arrives after the interval, so a 15 frames/s camera at 200 ms came at ~4/s, not 5.
      queue_length: s.throttleRate > 0 ? 1 : 0,
      reconnect_on_close: false,
    });
    s.current.subscribe(s.heard);
  }

  /** Resolves with the live connection, or null once the deadline passes. */
  private connectedWithin(deadline: number): Promise<ROSLIB.Ros | null> {
    return new Promise((resolve) => {
      const check = () => {
        if (this.status.state === "connected") return finish(this.ros);
        if (this.status.state === "closed" || Date.now() >= deadline) return finish(null);
      };
      // At the deadline whatever the clock says: a timer may fire a millisecond early, and nothing else would wake this.
      const timer = setTimeout(
        () => finish(this.status.state === "connected" ? this.ros : null),
        Math.max(0, deadline - Date.now()),
      );
      const finish = (ros: ROSLIB.Ros | null) => {
        clearTimeout(timer);
        this.waiting.delete(check);
        resolve(ros);
      };
      this.waiting.add(check);
      check();
    });
  }
}
