// Turns ajv's errors into plain sentences: for a plugin file, each with a
// precise JSON Pointer; for a value a researcher typed, the reason alone.
import type { ErrorObject } from "ajv";

export interface PlainError {
  path: string;
  reason: string;
}

const PATTERN_HINTS: Record<string, string> = {
  identifier: 'must be lower-case letters, digits, "-" or "_", starting with a letter or digit',
  topic: 'must be a ROS name like "/speech"',
  templatedTopic: 'must be a ROS name like "/speech", or one with {parameter} parts like "/sonar/{side}"',
  messageType: 'must be a ROS type like "std_msgs/msg/String"',
};

const ARTICLE: Record<string, string> = {
  integer: "a whole number",
  number: "a number",
  string: "a piece of text",
  boolean: "true or false",
  object: "an object",
  array: "a list",
  null: "empty",
};

const FORMAT: Record<string, string> = {
  email: "an email address",
  uri: "a web address",
  url: "a web address",
  date: "a date",
  time: "a time",
  "date-time": "a date and time",
  duration: "a duration",
  uuid: "an identifier (UUID)",
  hostname: "a host name",
  ipv4: "an IPv4 address",
  ipv6: "an IPv6 address",
};

const list = (values: unknown[]) => values.map((v) => JSON.stringify(v)).join(", ");
const counted = (n: unknown, one: string, many: string) => `${n} ${n === 1 ? one : many}`;

/**
 * What is wrong with a value, as the end of a sentence whose subject is the
 * value ("must be at most 10"): never ajv's own wording ("must NOT have more
 * than...").
 */
export function plainReason(error: ErrorObject): string {
  const params = error.params as Record<string, unknown>;
  switch (error.keyword) {
    case "required":
      return `needs "${String(params.missingProperty)}"`;
    case "type":
      return `must be ${String(params.type)
        .split(",")
        .map((t) => ARTICLE[t] ?? `a ${t}`)
        .join(" or ")}`;
    case "enum":
      return `must be one of: ${list(params.allowedValues as unknown[])}`;
    case "const":
      return `must be ${JSON.stringify(params.allowedValue)}`;
    case "minimum":
      return `must be at least ${params.limit}`;
    case "exclusiveMinimum":
      return `must be more than ${params.limit}`;
    case "maximum":
      return `must be at most ${params.limit}`;
    case "exclusiveMaximum":
      return `must be less than ${params.limit}`;
    case "multipleOf":
      return `must be a multiple of ${params.multipleOf}`;
    case "minLength":
      return params.limit === 1
        ? "must not be empty"
        : `must be at least ${counted(params.limit, "character", "characters")} long`;
    case "maxLength":
      return `must be at most ${counted(params.limit, "character", "characters")} long`;
    case "minItems":
      return `needs at least ${counted(params.limit, "entry", "entries")}`;
    case "maxItems":
      return `can have at most ${counted(params.limit, "entry", "entries")}`;
    case "uniqueItems": {
      const [first, second] = [Number(params.i), Number(params.j)].sort((a, b) => a - b);
      return `lists the same value twice (numbers ${first! + 1} and ${second! + 1})`;
    }
    case "minProperties":
      return `needs at least ${counted(params.limit, "entry", "entries")}`;
    case "maxProperties":
      return `can have at most ${counted(params.limit, "entry", "entries")}`;
    case "pattern":
      return "is not in the expected form";
    case "format":
      return `must be ${FORMAT[String(params.format)] ?? `a valid ${String(params.format)}`}`;
    case "additionalProperties":
      return `has a field "${String(params.additionalProperty)}" that does not belong here`;
    default:
      return "is not an accepted value here";
  }
}

export function plainErrors(errors: ErrorObject[] | null | undefined): PlainError[] {
  const seen = new Set<string>();
  const out: PlainError[] = [];
  for (const error of errors ?? []) {
    const plain = plain1(error);
    if (!plain) continue;
    const key = `${plain.path}\u0000${plain.reason}`;
    if (seen.has(key)) continue;
    seen.add(key);
    out.push(plain);
  }
  return out;
}

function plain1(error: ErrorObject): PlainError | null {
  const path = error.instancePath;
  const params = error.params as Record<string, unknown>;
  switch (error.keyword) {
    case "if":
      return null; // its "then" error says what is wrong
    case "not":
      // The one "not" of the schema: a service mapping on a topic or a ROS 2 action.
      return { path, reason: 'can be "service" only where the action names a "service" to call' };
    case "required":
      return { path: `${path}/${escapePointer(String(params.missingProperty))}`, reason: "is required but missing" };
    case "additionalProperties":
      return {
        path: `${path}/${escapePointer(String(params.additionalProperty))}`,
        reason: "is not an allowed field here",
      };
    case "pattern": {
      const definition = /definitions\/(\w+)\/pattern$/.exec(error.schemaPath)?.[1];
      if (definition && PATTERN_HINTS[definition]) return { path, reason: PATTERN_HINTS[definition] };
      if (error.schemaPath.includes("/version/")) return { path, reason: 'must be a version like "1.2.3"' };
      if (error.schemaPath.includes("/pluginApiVersion/"))
        return { path, reason: 'must be a 1.x plugin API version like "1.0"' };
      // Plugin authors read regular expressions; they wrote them.
      return { path, reason: `must match the pattern ${String(params.pattern)}` };
    }
    default:
      return { path, reason: plainReason(error) };
  }
}

function escapePointer(segment: string) {
  return segment.replace(/~/g, "~0").replace(/\//g, "~1");
}
