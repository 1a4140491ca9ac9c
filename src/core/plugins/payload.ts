// What goes on the wire for a resolved action: a topic message or service
// arguments, built from the plugin's payload mapping. SSH actions return their
// command template for the SSH transport to quote and run.
import { fillTemplate } from "./template";
import { TRANSFORMS } from "./transforms";
import type { JsonObject, JsonValue, PluginAction } from "./types";

export type Outgoing =
  | { kind: "publish"; topic: string; messageType: string; message: JsonValue }
  | { kind: "call"; service: string; serviceType: string; args: JsonValue }
  | { kind: "ssh"; command: string }
  | { kind: "none"; reason: string };

export function outgoingFor(action: PluginAction, parameters: Record<string, unknown>): Outgoing {
  const ros2 = action.ros2;
  if (!ros2) return { kind: "none", reason: `action "${action.id}" has no dispatch block` };
  if ("service" in ros2) {
    const args = fillTemplate(ros2.args ?? {}, parameters);
    if (!args.ok) return { kind: "none", reason: `${args.path}: ${args.reason}` };
    return { kind: "call", service: ros2.service, serviceType: ros2.serviceType, args: args.value };
  }
  const mapping = ros2.payloadMapping;
  if (mapping.type === "ssh") return { kind: "ssh", command: mapping.sshCommand };
  if (mapping.type === "transform") {
    const message: JsonObject = TRANSFORMS[mapping.transformFn]!(parameters);
    return { kind: "publish", topic: ros2.topic, messageType: ros2.messageType, message };
  }
  const message = fillTemplate(mapping.payload, parameters);
  if (!message.ok) return { kind: "none", reason: `${message.path}: ${message.reason}` };
  return { kind: "publish", topic: ros2.topic, messageType: ros2.messageType, message: message.value };
}
