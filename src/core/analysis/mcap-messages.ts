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

/** A schema being read off messages: every type seen, and (once seen) an object's properties, an array's items. */
interface Widening {
  types: Set<string>;
  properties?: Map<string, Widening>;
  items?: Widening;
}

/** Widens `w` to fit `value` too: one walk of the value, nothing built per message that fits already. */
function widen(w: Widening, value: unknown) {
  const type = typeOf(value);
  w.types.add(type);
  if (type === "array") {
    for (const item of value as unknown[]) widen((w.items ??= { types: new Set() }), item);
  } else if (type === "object") {
    w.properties ??= new Map();
    for (const [key, v] of Object.entries(value as object)) {
      let p = w.properties.get(key);
      if (!p) w.properties.set(key, (p = { types: new Set() }));
      widen(p, v);
    }
  }
}

/** The JSON Schema a widening reached: types in order (one alone as itself), properties in the order first met. */
function schemaFrom(w: Widening): JsonSchema {
  const all = [...w.types].sort();
  const out: JsonSchema = { type: all.length === 1 ? all[0] : all };
  if (w.properties) {
    // Without a prototype: a robot's field named __proto__ stays a field.
    const properties: Record<string, JsonSchema> = Object.create(null);
    for (const [key, p] of w.properties) properties[key] = schemaFrom(p);
    out.properties = properties;
  }
  if (w.items) out.items = schemaFrom(w.items);
  return out;
}

/** The JSON Schema every one of these messages (as JSON) fits: the fields they have, typed as they are. */
export function schemaOf(messages: unknown[]): JsonSchema {
  if (!messages.length) return { type: "object" };
  const w: Widening = { types: new Set() };
  for (const m of messages) widen(w, m);
  return schemaFrom(w);
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
