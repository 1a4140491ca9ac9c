// What the robot was sent for one action, as the transport puts it on the
// wire: the trial's dispatched event records it, so the events CSV, the trial
// JSON and the MCAP's robot-commands channel show the message itself, not
// only which action it was. Messages are kept as their JSON text, the bytes
// rosbridge sent: the log's jsonb would reorder an object's keys.
import type { Outgoing } from "./payload";

export type Sent =
  /** A topic message; a turn held then stopped also says its stop message and when that follows. */
  | { via: "topic"; topic: string; messageType: string; message: string; stopAfterMs?: number; stop?: string }
  | { via: "service"; service: string; serviceType: string; args: string }
  | { via: "action"; action: string; actionType: string; goal: string }
  | { via: "ssh"; command: string }
  | { via: "http"; method: string; url: string; body?: string };

const text = JSON.stringify;

/** What rosbridge sends for an outgoing action; null when it sends nothing (a topic read, or it cannot be built). */
export function sentOverRos(outgoing: Outgoing): Sent | null {
  switch (outgoing.kind) {
    case "publish":
      return {
        via: "topic",
        topic: outgoing.topic,
        messageType: outgoing.messageType,
        message: text(outgoing.message),
      };
    case "motion": {
      const { topic, messageType, message, stopAfterMs, stop } = outgoing;
      return { via: "topic", topic, messageType, message: text(message), stopAfterMs, stop: text(stop) };
    }
    case "call":
      return {
        via: "service",
        service: outgoing.service,
        serviceType: outgoing.serviceType,
        args: text(outgoing.args),
      };
    case "goal":
      return { via: "action", action: outgoing.action, actionType: outgoing.actionType, goal: text(outgoing.goal) };
    default:
      return null;
  }
}
