// How an action is known to be done, as its plugin declares it, and what
// confirmed it. Pure: the transports wait for what these functions say to
// wait for. A robot's answer (a done message that matches, a service
// response, an HTTP response, a ROS 2 action result) confirms an action; an
// estimated duration, or only the bridge having taken the message in, does
// not, and the log and the analysis say so.
import { fillTemplate } from "./template";
import type { Completion, DoneMatch, Expected, JsonValue, PluginAction } from "./types";

export type Rule = Completion | { kind: "command_exit" } | { kind: "delivered" };

/** What `action.completed` carries in its detail, under `confirmation`. */
export interface Confirmation {
  /** What said the action was done. */
  by:
    | "done_topic"
    | "service_response"
    | "http_response"
    | "action_result"
    | "command_exit"
    | "estimated_duration"
    | "delivered";
  /** True only when the robot itself said so. */
  confirmed: boolean;
  /** The done topic, service, URL or command that answered. */
  source?: string;
  /** The robot's own time of the answer (ISO 8601), when its message carries a header stamp. */
  robotTime?: string;
}

const CONFIRMED: ReadonlySet<Confirmation["by"]> = new Set([
  "done_topic",
  "service_response",
  "http_response",
  "action_result",
  "command_exit",
]);

export const isConfirmation = (by: Confirmation["by"]) => CONFIRMED.has(by);

/**
 * The action's rule: as declared, or what its dispatch gives by itself (a
 * service call's response, an HTTP response, a command's exit). A topic
 * publish without a rule only gets "delivered": the bridge read it.
 */
export function completionOf(action: PluginAction): Rule {
  if (action.completion) return action.completion;
  if (action.http) return { kind: "http_response" };
  const ros2 = action.ros2;
  if (ros2 && "service" in ros2) return { kind: "service_response" };
  if (ros2 && "payloadMapping" in ros2 && ros2.payloadMapping.type === "ssh") return { kind: "command_exit" };
  return { kind: "delivered" };
}

/** The done message this action waits for, its placeholders filled from the action's parameters. */
export function expectedDone(
  match: DoneMatch | undefined,
  parameters: Record<string, unknown>,
): { ok: true; match: DoneMatch | undefined } | { ok: false; reason: string } {
  if (!match) return { ok: true, match };
  const filled = fillTemplate(match as unknown as JsonValue, parameters);
  if (!filled.ok) return { ok: false, reason: `completion rule ${filled.path}: ${filled.reason}` };
  return { ok: true, match: filled.value as unknown as DoneMatch };
}

/**
 * Why a service's reply says it did not do the call, or null: rosbridge
 * carries a reply whose `success` is false (std_srvs/Trigger, SetBool) as a
 * successful call, but the robot has said no, with its `message`.
 */
export function serviceRefusal(service: string, reply: unknown): string | null {
  const { success, message } = (reply ?? {}) as { success?: unknown; message?: unknown };
  if (success !== false) return null;
  return `${service} answered that it did not succeed${typeof message === "string" && message ? `: ${message}` : ""}`;
}

/** Whether a message on the done topic is this action's: every condition of the (filled) match holds. */
export function matchesDone(match: DoneMatch | undefined, message: unknown): boolean {
  if (!match) return true;
  const value = fieldAt(message, match.field);
  if (match.equals !== undefined && !sameJson(value, match.equals)) return false;
  if (match.startsWith !== undefined && !(typeof value === "string" && value.startsWith(match.startsWith)))
    return false;
  return true;
}

/** How long the action is expected to take: fixed, plus so many ms per character of a text parameter. */
export function estimatedMs(rule: Expected, parameters: Record<string, unknown>) {
  const text = rule.perCharOf === undefined ? "" : String(parameters[rule.perCharOf] ?? "");
  return (rule.ms ?? 0) + (rule.msPerChar ?? 0) * [...text].length;
}

/** The robot's time in a message's header stamp (ROS 2 sec/nanosec, or ROS 1 secs/nsecs), as ISO 8601. */
export function robotTimeOf(message: unknown): string | undefined {
  const stamp = fieldAt(message, "header.stamp") as Record<string, unknown> | undefined;
  if (!stamp || typeof stamp !== "object") return undefined;
  const sec = Number(stamp.sec ?? stamp.secs);
  const nanosec = Number(stamp.nanosec ?? stamp.nsecs ?? 0);
  if (!Number.isFinite(sec) || !Number.isFinite(nanosec) || sec <= 0) return undefined;
  return new Date(sec * 1000 + Math.floor(nanosec / 1e6)).toISOString();
}

/** The value at a dotted path of a message ("header.stamp"), or undefined. */
export function fieldAt(message: unknown, path: string): unknown {
  let node = message;
  for (const key of path.split(".")) {
    if (node === null || typeof node !== "object") return undefined;
    node = (node as Record<string, unknown>)[key];
  }
  return node;
}

/**
 * A value as a match compares it: two values are the same when their keys
 * are. A string (a say's text, the usual match) is its own key, unserialised;
 * anything else is its JSON. Waiting actions are found by the key of the
 * value they expect (src/robots/transports/done-topics.ts).
 */
export const valueKey = (value: unknown): string =>
  typeof value === "string" ? `s${value}` : `j${JSON.stringify(value)}`;

const sameJson = (a: unknown, b: unknown) =>
  typeof a === "string" && typeof b === "string" ? a === b : valueKey(a) === valueKey(b);
