// What goes on the wire for a resolved action: a topic message, service
// arguments, a ROS 2 action goal, a turn held then stopped, or a topic to read
// once, built from the plugin's payload mapping. SSH actions return their
// command template for the SSH transport to quote and run.
import { unavailableReason } from "./availability";
import { actionGoal } from "./goal";
import { fillTemplate } from "./template";
import { dispatchName, fillName, nameParameters } from "./topic";
import { maxTurnOf, transformOf } from "./transforms";
import type { JsonObject, JsonValue, Plugin, PluginAction, PayloadMapping } from "./types";

export type Outgoing =
  | { kind: "publish"; topic: string; messageType: string; message: JsonValue }
  | { kind: "call"; service: string; serviceType: string; args: JsonValue }
  | { kind: "goal"; action: string; actionType: string; goal: JsonValue }
  /** Publish `message`, then `stop` once `stopAfterMs` have passed (or at once if the action is cut short). */
  | { kind: "motion"; topic: string; messageType: string; message: JsonValue; stopAfterMs: number; stop: JsonValue }
  /** Send nothing: take the next message of the topic, and complete with what `read` makes of it. */
  | { kind: "read"; topic: string; messageType: string; read: (message: unknown) => JsonObject }
  | { kind: "ssh"; command: string }
  | { kind: "none"; reason: string };

/** `plugin` gives what a transform needs of the robot as a whole (its top turning speed). */
export function outgoingFor(
  action: PluginAction,
  parameters: Record<string, unknown>,
  plugin: Pick<Plugin, "actions"> = { actions: [action] },
): Outgoing {
  const ros2 = action.ros2;
  if (!ros2) return { kind: "none", reason: `action "${action.id}" has no dispatch block` };
  const unavailable = unavailableReason(plugin, action);
  if (unavailable) return { kind: "none", reason: `action "${action.id}" cannot run: ${unavailable}` };
  const named = filledName(dispatchName(action)!, parameters);
  if (!named.ok) return { kind: "none", reason: named.reason };
  const name = named.name;
  if ("service" in ros2) {
    const args = fillTemplate(ros2.payloadMapping?.payload ?? ros2.args ?? {}, parameters);
    if (!args.ok) return { kind: "none", reason: `${args.path}: ${args.reason}` };
    // The schema asks for one of the two.
    return { kind: "call", service: name, serviceType: (ros2.serviceType ?? ros2.messageType)!, args: args.value };
  }
  const mapping = ros2.payloadMapping;
  if (mapping.type === "ssh") return { kind: "ssh", command: mapping.sshCommand };
  const transform = mapping.type === "transform" ? transformOf(mapping.transformFn)! : null;
  if (transform?.kind === "reading")
    return { kind: "read", topic: name, messageType: ros2.messageType, read: transform.read };
  if (transform?.kind === "motion") {
    const motion = transform.build(parameters, maxTurnOf(plugin)!);
    return { kind: "motion", topic: name, messageType: ros2.messageType, ...motion };
  }
  const message = transform ? { ok: true as const, value: transform.build(parameters) } : filled(mapping, parameters);
  if (!message.ok) return { kind: "none", reason: message.reason };
  if ("action" in ros2) {
    const goal = actionGoal(ros2, message.value as JsonObject);
    if (!goal.ok) return { kind: "none", reason: goal.reason };
    return { kind: "goal", action: name, actionType: goal.actionType, goal: goal.goal };
  }
  return { kind: "publish", topic: name, messageType: ros2.messageType, message: message.value };
}

/** A name without {parameter} parts is the plugin's as written; one with them is checked once filled. */
const filledName = (template: string, parameters: Record<string, unknown>) =>
  nameParameters(template).length ? fillName(template, parameters) : { ok: true as const, name: template };

function filled(mapping: PayloadMapping, parameters: Record<string, unknown>) {
  const payload = mapping.type === "static" ? mapping.payload : {};
  const result = fillTemplate(payload, parameters);
  return result.ok
    ? { ok: true as const, value: result.value }
    : { ok: false as const, reason: `${result.path}: ${result.reason}` };
}
