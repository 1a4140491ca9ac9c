// Topic and service names templated from the action's parameters, as
// HRIStudio's files write them: "/naoqi_driver/{sensor_type}_touch". Filled
// with the parameter's value as text, then checked as a ROS name, so a value
// cannot reach another namespace or send to a name rosbridge would refuse.
// Where every parameter a name uses has a fixed set of values (an enum), every
// name the action can reach is known before a trial: the portability report
// lists them and the simulated robot offers them.
import type { JsonObject, ParameterSchema, PluginAction, Ros2Dispatch } from "./types";

const PART = /\{([A-Za-z_][A-Za-z0-9_]*)\}/g;
// A ROS 2 name: the plugin schema's, and no empty part, no part that starts with a digit.
const ROS_NAME = /^\/?[A-Za-z_~][A-Za-z0-9_~]*(\/[A-Za-z_~][A-Za-z0-9_~]*)*$/;
/** More names than this from one action is not a fixed set worth listing. */
const MAX_NAMES = 256;

export type FilledName = { ok: true; name: string } | { ok: false; reason: string };

/** The parameters a templated name reads, in order. */
export function nameParameters(template: string): string[] {
  return [...new Set([...template.matchAll(PART)].map((m) => m[1]!))];
}

export function fillName(template: string, parameters: Record<string, unknown>): FilledName {
  let problem: string | null = null;
  const name = template.replace(PART, (_, parameter: string) => {
    const value = Object.hasOwn(parameters, parameter) ? parameters[parameter] : undefined;
    if (typeof value === "string" || typeof value === "number") return String(value);
    problem ??= `${template}: no text or number for parameter "${parameter}"`;
    return "";
  });
  if (problem) return { ok: false, reason: problem };
  if (ROS_NAME.test(name)) return { ok: true, name };
  const used = nameParameters(template)
    .map((p) => `${p} ${JSON.stringify(parameters[p])}`)
    .join(", ");
  return { ok: false, reason: `${template}: with ${used} it is ${JSON.stringify(name)}, which is not a ROS name` };
}

/** The field of a dispatch that names where it goes: its topic, service or ROS 2 action. */
export const dispatchField = (ros2: Ros2Dispatch) =>
  "service" in ros2 ? ("service" as const) : "action" in ros2 ? ("action" as const) : ("topic" as const);

/** The templated name of an action's dispatch. */
export function dispatchName(action: PluginAction): string | null {
  const ros2 = action.ros2;
  if (!ros2) return null;
  return "service" in ros2 ? ros2.service : "action" in ros2 ? ros2.action : ros2.topic;
}

/** The template of what a dispatch sends (a message, or a service call's arguments), with its pointer under the action. */
export function messageTemplate(ros2: Ros2Dispatch): { at: string; template: JsonObject } {
  if ("service" in ros2 && !ros2.payloadMapping) return { at: "/ros2/args", template: ros2.args ?? {} };
  const mapping = ros2.payloadMapping!;
  return { at: "/ros2/payloadMapping/payload", template: (mapping.type !== "ssh" && mapping.payload) || {} };
}

export type ReachableNames = { names: string[] } | { open: string[] } | { ok: false; reason: string };

/**
 * Every name a templated name can become: each fixed value of each parameter
 * it reads; `open` lists the parameters without fixed values (any text), and
 * a fixed value that makes no ROS name is the reason the action cannot run.
 */
export function reachableNames(template: string, schema: ParameterSchema): ReachableNames {
  const used = nameParameters(template);
  const open = used.filter((p) => !Array.isArray(schema.properties[p]?.enum));
  if (open.length) return { open };
  let combinations: Array<Record<string, unknown>> = [{}];
  for (const parameter of used) {
    const values = schema.properties[parameter]!.enum as unknown[];
    combinations = combinations.flatMap((c) => values.map((v) => ({ ...c, [parameter]: v })));
    if (combinations.length > MAX_NAMES) return { open: [] };
  }
  const names: string[] = [];
  for (const combination of combinations) {
    const filled = fillName(template, combination);
    if (!filled.ok) return filled;
    if (!names.includes(filled.name)) names.push(filled.name);
  }
  return { names };
}
