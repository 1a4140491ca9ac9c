// The simulated ROS graph: topics with one type each, the callbacks
// subscribed to them (robot nodes and client connections alike), and the
// services the robot (or a client, by advertise_service) offers. A topic is
// known while someone declares it: the robot (for good) or a client that
// advertised or subscribed with a type. A topic a client advertised with
// latch keeps its last message for each new subscriber.
import { lookupType } from "./ros-types";

type Listener = (message: Record<string, unknown>) => void;
export type ServiceHandler = (
  request: Record<string, unknown>,
) => Record<string, unknown> | Promise<Record<string, unknown>>;

/** A ROS 2 action server: runs one goal, may send feedback, resolves with the result unless cancelled. */
export type ActionHandler = (
  goal: Record<string, unknown>,
  run: { feedback(values: Record<string, unknown>): void; cancelled: Promise<void> },
) => Promise<Record<string, unknown>>;

/** A service a client offers: `displaced` is told when another advertisement takes its name. */
export interface ClientService {
  typeKey: string;
  handler: ServiceHandler;
  owner: string;
  displaced(): void;
}

interface Topic {
  typeKey: string;
  owners: Set<string>;
}

export class RosGraph {
  private readonly topics = new Map<string, Topic>();
  private readonly listeners = new Map<string, Set<Listener>>();
  readonly services = new Map<string, { typeKey: string; handler: ServiceHandler; owner?: string }>();
  /** The robot's own services that a client's advertisement hides for now. */
  private readonly hidden = new Map<string, { typeKey: string; handler: ServiceHandler }>();
  /** rosbridge's one publisher per topic, shared by the clients that advertised it; latched or not as the first said. */
  private readonly publishers = new Map<
    string,
    { latch: boolean; owners: Set<string>; last?: Record<string, unknown> }
  >();
  readonly actions = new Map<string, { typeKey: string; handler: ActionHandler }>();

  /** Declares a topic's type for an owner; returns an error text on a conflict. */
  declare(topic: string, type: string, owner: string): string | null {
    const lookup = lookupType(type);
    if (!lookup.ok) return lookup.reason;
    const existing = this.topics.get(topic);
    if (existing && existing.typeKey !== lookup.key) {
      return `Tried to register topic ${topic} with type ${type} but it is already established with type ${existing.typeKey.replace("/", "/msg/")}`;
    }
    if (existing) existing.owners.add(owner);
    else this.topics.set(topic, { typeKey: lookup.key, owners: new Set([owner]) });
    return null;
  }

  release(topic: string, owner: string) {
    const existing = this.topics.get(topic);
    if (!existing) return;
    existing.owners.delete(owner);
    if (existing.owners.size === 0) this.topics.delete(topic);
  }

  typeOf(topic: string): string | undefined {
    return this.topics.get(topic)?.typeKey;
  }

  listen(topic: string, listener: Listener): () => void {
    let set = this.listeners.get(topic);
    if (!set) this.listeners.set(topic, (set = new Set()));
    set.add(listener);
    return () => set.delete(listener);
  }

  publish(topic: string, message: Record<string, unknown>) {
    for (const listener of [...(this.listeners.get(topic) ?? [])]) listener(message);
  }

  /**
   * A client's advertise_service. rosbridge keeps one advertiser per name:
   * the newest wins, the one before is displaced (its calls in flight fail).
   * Returns whether a client's service was overwritten.
   */
  advertiseService(name: string, service: ClientService): boolean {
    const previous = this.services.get(name);
    if (previous && !previous.owner) this.hidden.set(name, previous);
    this.services.set(name, service);
    if (previous?.owner) (previous as ClientService).displaced();
    return Boolean(previous?.owner);
  }

  /** The owner's advertisement ends; the robot's own service of that name, if any, is back. */
  withdrawService(name: string, owner: string) {
    if (this.services.get(name)?.owner !== owner) return;
    const robot = this.hidden.get(name);
    this.hidden.delete(name);
    if (robot) this.services.set(name, robot);
    else this.services.delete(name);
  }

  /** A client's advertise: returns a warning when it asks for another latch than the topic's publisher has. */
  addPublisher(topic: string, owner: string, latch: boolean): string | null {
    const existing = this.publishers.get(topic);
    if (!existing) {
      this.publishers.set(topic, { latch, owners: new Set([owner]) });
      return null;
    }
    existing.owners.add(owner);
    if (latch === existing.latch) return null;
    return latch
      ? `Client attempted to register topic [${topic}] as latched but this topic was previously registered`
      : `New non-latched publisher registration for topic [${topic}] which is already registered as latched`;
  }

  /** The publisher goes, and its latched message with it, once no client advertises the topic. */
  removePublisher(topic: string, owner: string) {
    const existing = this.publishers.get(topic);
    if (!existing) return;
    existing.owners.delete(owner);
    if (existing.owners.size === 0) this.publishers.delete(topic);
  }

  /** A client's publish: kept as the topic's latched message when its publisher latches. */
  publishFromClient(topic: string, message: Record<string, unknown>) {
    const publisher = this.publishers.get(topic);
    if (publisher?.latch) publisher.last = message;
    this.publish(topic, message);
  }

  /** What a new subscriber gets at once: the latched message, if the topic has one. */
  latched(topic: string): Record<string, unknown> | undefined {
    return this.publishers.get(topic)?.last;
  }

  offerAction(name: string, type: string, handler: ActionHandler) {
    const lookup = lookupType(type, "action");
    if (!lookup.ok) throw new Error(lookup.reason);
    this.actions.set(name, { typeKey: lookup.key, handler });
  }

  offer(name: string, type: string, handler: ServiceHandler) {
    const lookup = lookupType(type, "srv");
    if (!lookup.ok) throw new Error(lookup.reason);
    this.services.set(name, { typeKey: lookup.key, handler });
  }
}
