// Turns ajv's errors into plain sentences with a precise JSON Pointer.
import type { ErrorObject } from "ajv";

export interface PlainError {
  path: string;
  reason: string;
}

const PATTERN_HINTS: Record<string, string> = {
  identifier: 'must be lower-case letters, digits, "-" or "_", starting with a letter or digit',
  topic: 'must be a ROS name like "/speech"',
  messageType: 'must be a ROS type like "std_msgs/msg/String"',
};

const ARTICLE: Record<string, string> = { integer: "an integer", object: "an object", array: "a list" };

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
    case "required":
      return { path: `${path}/${escapePointer(String(params.missingProperty))}`, reason: "is required but missing" };
    case "additionalProperties":
      return {
        path: `${path}/${escapePointer(String(params.additionalProperty))}`,
        reason: "is not an allowed field here",
      };
    case "type": {
      const types = String(params.type).split(",");
      return { path, reason: `must be ${types.map((t) => ARTICLE[t] ?? `a ${t}`).join(" or ")}` };
    }
    case "enum":
      return {
        path,
        reason: `must be one of: ${(params.allowedValues as unknown[]).map((v) => JSON.stringify(v)).join(", ")}`,
      };
    case "const":
      return { path, reason: `must be ${JSON.stringify(params.allowedValue)}` };
    case "pattern": {
      const definition = /definitions\/(\w+)\/pattern$/.exec(error.schemaPath)?.[1];
      if (definition && PATTERN_HINTS[definition]) return { path, reason: PATTERN_HINTS[definition] };
      if (error.schemaPath.includes("/version/")) return { path, reason: 'must be a version like "1.2.3"' };
      if (error.schemaPath.includes("/pluginApiVersion/"))
        return { path, reason: 'must be a 1.x plugin API version like "1.0"' };
      return { path, reason: `must match the pattern ${String(params.pattern)}` };
    }
    default:
      return { path, reason: error.message ?? error.keyword };
  }
}

function escapePointer(segment: string) {
  return segment.replace(/~/g, "~0").replace(/\//g, "~1");
}
