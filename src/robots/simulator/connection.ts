// One client connection, speaking rosbridge v2 the way the recorded server
// does: no status frames and no acknowledgements (errors go to the log
// only), state that belongs to this connection alone, stream parsing of
// incoming text, fragments both ways. Services a client advertises
// (advertised-services.ts) and latched topics follow rosbridge_suite's code.
// Two server faults are imitated on purpose because clients must survive
// them: a bare JSON number, null or boolean stops all processing on the
// connection (07), and a non-integer fragment_size makes it mute (05).
// Either way the socket stays open.
import { ActionGoals } from "./action-goals";
import { AdvertisedServices } from "./advertised-services";
import { ServiceCalls } from "./service-calls";
import type { RosGraph } from "./graph";
import { messageJson, populate } from "./ros-types";
import { IncomingStream } from "./stream";
import { Subscription } from "./subscription";
import { encode, encodePublish, fragments } from "./wire";
import { optionalInteger, requireString } from "./fields";

export interface ConnectionHooks {
  send(text: string): void;
  log(text: string): void;
  record(message: Record<string, unknown>): void;
  /** Also tell the client what was refused, as a `status` frame (protocol.md); the recorded servers never do. */
  statusFrames?: boolean;
}

type Message = Record<string, unknown>;

export class Connection {
  private readonly stream = new IncomingStream();
  private readonly subscriptions = new Map<string, { subscription: Subscription; stop: () => void }>();
  private readonly advertised = new Map<string, Set<unknown>>();
  private readonly partial = new Map<unknown, { total: unknown; parts: Map<unknown, string> }>();
  private readonly calls: ServiceCalls;
  private readonly goals: ActionGoals;
  private readonly offered: AdvertisedServices;
  private fragmentSize: unknown = null;
  /** rosbridge's worker thread died: nothing sent on this connection is processed. */
  private deaf = false;

  constructor(
    readonly id: string,
    private readonly graph: RosGraph,
    private readonly hooks: ConnectionHooks,
  ) {
    this.calls = new ServiceCalls(graph, (m) => this.send(m), hooks.log);
    this.goals = new ActionGoals(graph, (m) => this.send(m), hooks.log);
    this.offered = new AdvertisedServices(graph, this.owner, (m) => this.send(m), hooks.log);
  }

  receive(text: string) {
    if (this.deaf) return;
    for (let found = this.stream.next(text); found; found = this.stream.pending ? this.stream.next("") : undefined) {
      this.handle(found.message);
      if (this.deaf) return;
    }
  }

  close() {
    this.goals.close();
    this.offered.close();
    for (const { subscription, stop } of this.subscriptions.values()) {
      subscription.close();
      stop();
    }
    this.subscriptions.clear();
    for (const topic of this.advertised.keys()) {
      this.graph.release(topic, this.owner);
      this.graph.removePublisher(topic, this.owner);
    }
    this.advertised.clear();
  }

  private get owner() {
    return `client:${this.id}`;
  }

  private handle(message: unknown) {
    if (message === null || typeof message !== "object") {
      // Python's `"id" in msg` raises on numbers, null and booleans, and
      // `msg["op"]` on a string that contains "op" or "id".
      if (typeof message !== "string" || message.includes("op") || message.includes("id")) {
        this.deaf = true;
        return this.hooks.log(`connection stops processing after a bare JSON ${JSON.stringify(message)}`);
      }
    }
    if (Array.isArray(message) || typeof message !== "object" || message === null)
      return this.hooks.log("received a message without an op");
    const m = message as Message;
    this.hooks.record(m);
    if (!("op" in m))
      return this.hooks.log("receiver" in m ? "received a rosbridge v1.0 message" : "received a message without an op");
    const handler = this.ops[m.op as string];
    if (typeof m.op !== "string" || !handler) return this.hooks.log(`unknown operation: ${String(m.op)}`);
    if ("fragment_size" in m) this.fragmentSize = m.fragment_size;
    try {
      handler(m);
    } catch (error) {
      const text = `${m.op}: ${(error as Error).message}`;
      this.hooks.log(text);
      if (this.hooks.statusFrames)
        this.send({ op: "status", ...(m.id !== undefined ? { id: m.id } : {}), level: "error", msg: text });
    }
  }

  private readonly ops: Record<string, (m: Message) => void> = {
    advertise: (m) => {
      const topic = requireString(m, "topic");
      if (!("type" in m)) throw new Error("missing type");
      const conflict = this.graph.declare(topic, String(m.type), this.owner);
      if (conflict) throw new Error(conflict);
      const ids = this.advertised.get(topic) ?? new Set();
      this.advertised.set(topic, ids.add(m.id ?? null));
      const warning = this.graph.addPublisher(topic, this.owner, m.latch === true);
      if (warning) this.hooks.log(warning);
    },
    unadvertise: (m) => {
      const topic = requireString(m, "topic");
      const ids = this.advertised.get(topic);
      if (!ids) return;
      ids.delete(m.id ?? null);
      if (ids.size && m.id !== undefined) return;
      this.advertised.delete(topic);
      this.graph.release(topic, this.owner);
      this.graph.removePublisher(topic, this.owner);
    },
    publish: (m) => {
      const topic = requireString(m, "topic");
      const typeKey = this.graph.typeOf(topic);
      if (!typeKey) throw new Error(`Cannot infer topic type for topic ${topic} as it is not yet advertised`);
      if ("msg" in m && (typeof m.msg !== "object" || m.msg === null || Array.isArray(m.msg)))
        throw new Error("msg must be an object");
      this.graph.publishFromClient(topic, populate(typeKey, m.msg));
    },
    subscribe: (m) => {
      const topic = requireString(m, "topic");
      const throttleRate = optionalInteger(m, "throttle_rate");
      const queueLength = optionalInteger(m, "queue_length");
      if ("type" in m && m.type !== undefined) {
        const conflict = this.graph.declare(topic, String(m.type), this.owner);
        if (conflict) throw new Error(conflict);
      } else if (!this.graph.typeOf(topic)) {
        throw new Error(`Cannot infer topic type for topic ${topic} as it is not yet advertised`);
      }
      let entry = this.subscriptions.get(topic);
      if (!entry) {
        const subscription = new Subscription((msg) =>
          this.send({ op: "publish", topic, msg }, encodePublish(topic, messageJson(this.graph.typeOf(topic), msg))),
        );
        entry = { subscription, stop: this.graph.listen(topic, (msg) => subscription.deliver(msg)) };
        this.subscriptions.set(topic, entry);
        entry.subscription.add((m.id as string | undefined) ?? null, { throttleRate, queueLength });
        // A new subscriber of a latched topic gets its last message at once (a further id on the topic does not).
        const latched = this.graph.latched(topic);
        if (latched) subscription.deliver(latched);
        return;
      }
      entry.subscription.add((m.id as string | undefined) ?? null, { throttleRate, queueLength });
    },
    unsubscribe: (m) => {
      const topic = requireString(m, "topic");
      const entry = this.subscriptions.get(topic);
      if (!entry) return;
      if (entry.subscription.remove((m.id as string | undefined) ?? null)) {
        entry.stop();
        this.subscriptions.delete(topic);
      }
    },
    call_service: (m) => this.calls.call(m),
    advertise_service: (m) => this.offered.advertise(m),
    unadvertise_service: (m) => this.offered.unadvertise(m),
    service_response: (m) => this.offered.respond(m),
    send_action_goal: (m) => this.goals.goal(m),
    cancel_action_goal: (m) => this.goals.cancel(m),
    fragment: (m) => this.defragment(m),
  };

  /** Reassembled in arrival order once every num 0..total-1 is present (transcript 08). */
  private defragment(m: Message) {
    let entry = this.partial.get(m.id);
    if (!entry) this.partial.set(m.id, (entry = { total: m.total, parts: new Map() }));
    entry.parts.set(m.num, String(m.data));
    if (m.total !== entry.total || entry.parts.size !== entry.total) return;
    for (let i = 0; i < (entry.total as number); i++) {
      if (!entry.parts.has(i)) return this.hooks.log(`fragment #${i} for message ${String(m.id)} is missing`);
    }
    this.partial.delete(m.id);
    this.receive([...entry.parts.values()].join(""));
  }

  private send(message: Message, text = encode(message)) {
    const size = this.fragmentSize;
    if (size !== null && !Number.isInteger(size))
      return this.hooks.log(`cannot send: fragment_size ${JSON.stringify(size)} is not an integer`);
    const frames = size === null ? [text] : fragments(text, size as number, message.id);
    for (const frame of frames) this.hooks.send(frame);
  }
}
