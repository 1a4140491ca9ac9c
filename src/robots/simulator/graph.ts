// The simulated ROS graph: topics with one type each, the callbacks
// subscribed to them (robot nodes and client connections alike), and the
// services the robot offers. A topic is known while someone declares it: the
// robot (for good) or a client that advertised or subscribed with a type.
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

interface Topic {
  typeKey: string;
  owners: Set<string>;
}

export class RosGraph {
  private readonly topics = new Map<string, Topic>();
  private readonly listeners = new Map<string, Set<Listener>>();
  readonly services = new Map<string, { typeKey: string; handler: ServiceHandler }>();
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
