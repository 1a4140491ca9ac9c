// What a trial's MCAP file holds, in Foxglove's terms: each topic's JSON
// Schema read off the messages it carries (so Foxglove lists and plots their
// fields), trial events as foxglove.Log, and times as integer nanoseconds.
import type { StoredEvent } from "@/core/trial";

/** The part of JSON Schema the MCAP's channels use: types, an object's properties, an array's items. */
export interface JsonSchema {
  type?: string | string[];
  properties?: Record<string, JsonSchema>;
  items?: JsonSchema;
  [more: string]: unknown;
}

const typeOf = (value: unknown) =>
  value === null ? "null" : Array.isArray(value) ? "array" : typeof value === "object" ? "object" : typeof value;

const types = (s: JsonSchema) => (s.type === undefined ? [] : Array.isArray(s.type) ? s.type : [s.type]);

/** Two shapes as one: every type either allows, properties and items merged. */
function merged(a: JsonSchema, b: JsonSchema): JsonSchema {
  const all = [...new Set([...types(a), ...types(b)])].sort();
  const out: JsonSchema = { type: all.length === 1 ? all[0] : all };
  if (a.properties || b.properties) {
    // Without a prototype: a robot's field named __proto__ stays a field.
    const properties: Record<string, JsonSchema> = Object.assign(Object.create(null), a.properties);
    for (const [key, shape] of Object.entries(b.properties ?? {}))
      properties[key] = properties[key] ? merged(properties[key], shape) : shape;
    out.properties = properties;
  }
  if (a.items || b.items) out.items = a.items && b.items ? merged(a.items, b.items) : (a.items ?? b.items);
  return out;
}

function shapeOf(value: unknown): JsonSchema {
  const type = typeOf(value);
  if (type === "array") {
    const items = (value as unknown[]).map(shapeOf);
    return items.length ? { type, items: items.reduce(merged) } : { type };
  }
  if (type === "object")
    return {
      type,
      properties: Object.fromEntries(Object.entries(value as object).map(([k, v]) => [k, shapeOf(v)])),
    };
  return { type };
}

/** The JSON Schema every one of these messages (as JSON) fits: the fields they have, typed as they are. */
export function schemaOf(messages: unknown[]): JsonSchema {
  return messages.length ? messages.map(shapeOf).reduce(merged) : { type: "object" };
}

/**
 * The message a chart can plot: a robot state sent as a std_msgs/String holding JSON (the simulated
 * robot's report) becomes that JSON's object, so its numbers are numbers, not text.
 */
export function plottable(data: unknown): unknown {
  if (typeOf(data) !== "object") return data;
  const entries = Object.entries(data as object);
  if (entries.length !== 1 || entries[0]![0] !== "data" || typeof entries[0]![1] !== "string") return data;
  try {
    const inner = JSON.parse(entries[0]![1]);
    return typeOf(inner) === "object" ? inner : data;
  } catch {
    return data;
  }
}

/**
 * A topic's schema name: the ROS type the robot declared for it (`rosType`, null where it gave none or
 * the message was unwrapped), else sensor_msgs/JointState where the messages are joint states (Foxglove's
 * joint panels know it), else one per topic.
 */
export function sampleSchemaName(topic: string, schema: JsonSchema, rosType: string | null = null): string {
  if (rosType) return rosType;
  const p = schema.properties ?? {};
  const names = p.name?.type === "array" && p.name.items?.type === "string";
  if (names && p.position?.type === "array") return "sensor_msgs/JointState";
  return `hristudio.robot${topic.replace(/[^A-Za-z0-9_]+/g, ".").replace(/\.$/, "")}`;
}

/** Nanoseconds since the epoch of `relMs` after `startMs`, kept whole: epoch nanoseconds pass 2^53, so no float holds them. */
export function nanosecondsAt(startMs: number, relMs: number): bigint {
  return BigInt(Math.trunc(startMs)) * 1_000_000n + BigInt(Math.round(relMs * 1_000_000));
}

// foxglove.Log's JSON Schema, as Foxglove publishes it (its log panel reads this name).
const TIME = {
  type: "object",
  title: "time",
  properties: {
    sec: { type: "integer", minimum: 0 },
    nsec: { type: "integer", minimum: 0, maximum: 999_999_999 },
  },
};
export const LOG_SCHEMA: JsonSchema = {
  title: "foxglove.Log",
  description: "A log message",
  type: "object",
  properties: {
    timestamp: { ...TIME, description: "Timestamp of log message" },
    level: {
      title: "foxglove.LogLevel",
      description: "Log level",
      oneOf: ["UNKNOWN", "DEBUG", "INFO", "WARNING", "ERROR", "FATAL"].map((title, i) => ({ title, const: i })),
    },
    message: { type: "string", description: "Log message" },
    name: { type: "string", description: "Process or node name" },
    file: { type: "string", description: "Filename" },
    line: { type: "integer", minimum: 0, description: "Line number in the file" },
  },
};

const INFO = 2;
const WARNING = 3;
const ERROR = 4;
// What went wrong or off script shows as a warning, a stopped trial as an error, the rest as information.
const LEVELS: Record<string, number> = {
  "action.failed": WARNING,
  "action.timed_out": WARNING,
  "robot.problem": WARNING,
  "trial.emergency_stop": ERROR,
  "trial.aborted": ERROR,
};

/**
 * A trial event as a foxglove.Log, logged at `logged` nanoseconds: its type, then its fields as JSON. What the robot
 * sensed is stamped with the robot's own time (its fields keep the message that matched).
 */
export function logOf(event: StoredEvent, logged: bigint) {
  const { type, seq: _seq, relMs: _relMs, trialId: _trialId, serverTime: _serverTime, ...fields } = event;
  const rest = Object.keys(fields).length ? ` ${JSON.stringify(fields)}` : "";
  const at = event.type === "robot.sensed" ? nanosecondsAt(event.at, 0) : logged;
  return {
    timestamp: { sec: Number(at / 1_000_000_000n), nsec: Number(at % 1_000_000_000n) },
    level: LEVELS[type] ?? (event.deviation ? WARNING : INFO),
    message: type + rest,
    name: "hristudio",
    file: "",
    line: 0,
  };
}
