// The ROS message and service types the simulated robot knows, and the
// conversion rosbridge does from JSON to a message: missing fields take their
// defaults, an unknown field or a wrong type is an error. ROS 2 flavour: both
// "pkg/msg/Type" and "pkg/Type" are accepted (the ROS 2 server splits on "/"
// and keeps the first and last parts), times are {sec, nanosec}, Header has no seq.
// The messages themselves are declared once, in the core (the plugin loader reads them too).
import { type Definition, type Field, MESSAGES } from "../../core/robots/messages";

const SERVICES: Record<string, { request: Definition; response: Definition }> = {
  "std_srvs/SetBool": { request: { data: "bool" }, response: { success: "bool", message: "string" } },
  "std_srvs/Trigger": { request: {}, response: { success: "bool", message: "string" } },
  "std_srvs/Empty": { request: {}, response: {} },
};

/** ROS 2 actions: the goal's fields (rosbridge's send_action_goal fills it as it fills a message). */
const ACTIONS: Record<string, { goal: Definition }> = {
  "nav2_msgs/NavigateToPose": { goal: { pose: "geometry_msgs/PoseStamped", behavior_tree: "string" } },
};

const INTEGER_RANGES: Record<string, [number, number]> = {
  int8: [-128, 127],
  uint8: [0, 255],
  int16: [-32768, 32767],
  uint16: [0, 65535],
  int32: [-2147483648, 2147483647],
  uint32: [0, 4294967295],
  int64: [Number.MIN_SAFE_INTEGER, Number.MAX_SAFE_INTEGER],
  uint64: [0, Number.MAX_SAFE_INTEGER],
};

export type TypeLookup = { ok: true; key: string; spelling: string } | { ok: false; reason: string };

/** "std_msgs/msg/String" and "std_msgs/String" both give key "std_msgs/String". */
export function lookupType(name: unknown, kind: "msg" | "srv" | "action" = "msg"): TypeLookup {
  if (typeof name !== "string") return { ok: false, reason: `${JSON.stringify(name)} is not a valid type string` };
  const parts = name.split("/");
  if (parts.length < 2 || parts.length > 3 || parts.some((p) => !p) || (parts.length === 3 && parts[1] !== kind)) {
    return { ok: false, reason: `${name} is not a valid type string` };
  }
  const key = `${parts[0]}/${parts[parts.length - 1]}`;
  const table = kind === "msg" ? MESSAGES : kind === "srv" ? SERVICES : ACTIONS;
  if (!table[key]) {
    const knownPackage = Object.keys(table).some((k) => k.startsWith(`${parts[0]}/`));
    return {
      ok: false,
      reason: knownPackage
        ? `Unable to import ${kind} class ${parts[parts.length - 1]} from package ${parts[0]}`
        : `Unable to load the manifest for package ${parts[0]}`,
    };
  }
  return { ok: true, key, spelling: `${parts[0]}/${kind}/${parts[parts.length - 1]}` };
}

export class ConversionError extends Error {}

const FLOATS = new Set(["float32", "float64"]);

/**
 * A message as rosbridge writes it: Python floats keep their ".0" (1.0, not
 * 1, so a Python client reads a float back) and NaN and ±Infinity are null,
 * as rosbridge's message conversion turns them (ROS 1 and ROS 2 branches
 * alike), though it reads their literals. Other values as JSON.
 */
export function messageJson(typeKey: string | undefined, value: unknown): string {
  return typeKey && MESSAGES[typeKey] ? write(typeKey, value) : JSON.stringify(value);
}

function write(type: Field, value: unknown): string {
  if (type.endsWith("[]") && Array.isArray(value))
    return `[${value.map((v) => write(type.slice(0, -2), v)).join(",")}]`;
  const definition = MESSAGES[type];
  if (definition && value && typeof value === "object" && !Array.isArray(value)) {
    const fields = Object.entries(value as Record<string, unknown>).map(
      ([k, v]) => `${JSON.stringify(k)}:${definition[k] ? write(definition[k]!, v) : JSON.stringify(v)}`,
    );
    return `{${fields.join(",")}}`;
  }
  if (FLOATS.has(type) && typeof value === "number") return floatText(value);
  return JSON.stringify(value);
}

function floatText(value: number): string {
  if (!Number.isFinite(value)) return "null";
  const text = String(value);
  return /[.e]/.test(text) ? text : `${text}.0`;
}

/** JSON to a full message of the type, as rosbridge's populate_instance does. */
export function populate(typeKey: string, value: unknown): Record<string, unknown> {
  return populateWith(MESSAGES[typeKey]!, typeKey, value);
}

export function populateGoal(actionKey: string, value: unknown): Record<string, unknown> {
  return populateWith(ACTIONS[actionKey]!.goal, `${actionKey}Goal`, value);
}

export function populateRequest(serviceKey: string, value: unknown): Record<string, unknown> {
  return populateWith(SERVICES[serviceKey]!.request, `${serviceKey}Request`, value);
}

export function populateResponse(serviceKey: string, value: unknown): Record<string, unknown> {
  return populateWith(SERVICES[serviceKey]!.response, `${serviceKey}Response`, value);
}

function populateWith(definition: Definition, typeName: string, value: unknown): Record<string, unknown> {
  const given = (value ?? {}) as Record<string, unknown>;
  if (typeof given !== "object" || Array.isArray(given))
    throw new ConversionError(`Message type ${typeName} requires an object, but got ${describe(value)}`);
  for (const key of Object.keys(given)) {
    if (!Object.hasOwn(definition, key))
      throw new ConversionError(`Message type ${typeName} does not have a field ${key}`);
  }
  const out: Record<string, unknown> = {};
  for (const [field, type] of Object.entries(definition)) {
    out[field] = Object.hasOwn(given, field) ? convert(type, given[field], typeName, field) : defaultOf(type);
  }
  return out;
}

function convert(type: Field, value: unknown, typeName: string, field: string): unknown {
  if (type.endsWith("[]")) {
    if (!Array.isArray(value))
      throw new ConversionError(`${typeName} message requires a list for field ${field}, but got ${describe(value)}`);
    return value.map((item) => convert(type.slice(0, -2), item, typeName, field));
  }
  if (
    type === "builtin_interfaces/Time" &&
    value &&
    typeof value === "object" &&
    ("secs" in value || "nsecs" in value)
  ) {
    const { secs = 0, nsecs = 0 } = value as { secs?: unknown; nsecs?: unknown };
    value = { sec: secs, nanosec: nsecs };
  }
  if (MESSAGES[type]) return populateWith(MESSAGES[type]!, type, value);
  const wrong = () =>
    new ConversionError(`${typeName} message requires a ${type} for field ${field}, but got ${describe(value)}`);
  if (type === "string") {
    if (typeof value !== "string") throw wrong();
    if (/[\ud800-\udbff](?![\udc00-\udfff])|(?<![\ud800-\udbff])[\udc00-\udfff]/.test(value)) {
      throw new ConversionError(`field ${field}: a lone surrogate cannot be encoded as UTF-8`);
    }
    return value;
  }
  if (type === "bool") {
    if (typeof value !== "boolean") throw wrong();
    return value;
  }
  // NaN and ±Infinity are floats to Python: a float field takes them (BatteryState's unmeasured fields are NaN), an integer field does not.
  if (typeof value !== "number" || (!Number.isFinite(value) && !FLOATS.has(type))) throw wrong();
  const range = INTEGER_RANGES[type];
  if (range && (!Number.isInteger(value) || value < range[0] || value > range[1])) throw wrong();
  return value;
}

function defaultOf(type: Field): unknown {
  if (type.endsWith("[]")) return [];
  if (MESSAGES[type]) return populateWith(MESSAGES[type]!, type, {});
  if (type === "string") return "";
  if (type === "bool") return false;
  return 0;
}

function describe(value: unknown): string {
  if (value === null) return "null";
  if (Array.isArray(value)) return "a list";
  if (typeof value === "number") return Number.isInteger(value) ? "an int" : "a float";
  return `a ${typeof value === "string" ? "str" : typeof value}`;
}

export function requestFields(serviceKey: string): string[] {
  return Object.keys(SERVICES[serviceKey]!.request);
}
