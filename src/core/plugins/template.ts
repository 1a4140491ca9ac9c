// Payload templates: {{param}} placeholders filled as JSON values by walking
// the parsed template, never by building JSON text. A string that is exactly
// "{{x}}" becomes x's JSON value (a number stays a number); a placeholder
// inside a longer string is replaced by the value as text, in one pass, so a
// parameter whose text itself contains "{{x}}", quotes, braces, backslashes
// or newlines arrives exactly as given.
import type { JsonValue } from "./types";

const PLACEHOLDER = /\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}/g;
const WHOLE = /^\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}$/;
const MAX_DEPTH = 64;

export type FillResult = { ok: true; value: JsonValue } | { ok: false; path: string; reason: string };

export function fillTemplate(template: JsonValue, parameters: Record<string, unknown>): FillResult {
  const missing: { path: string; name: string }[] = [];
  const value = walk(template, "", 0, (name, path) => {
    if (Object.hasOwn(parameters, name) && parameters[name] !== undefined) return parameters[name] as JsonValue;
    missing.push({ path, name });
    return null;
  });
  const first = missing[0];
  if (first) return { ok: false, path: first.path, reason: `no value for parameter "${first.name}"` };
  return { ok: true, value };
}

/** Every placeholder in a template with the JSON Pointer of the string holding it. */
export function placeholders(template: unknown, base = ""): Array<{ path: string; name: string }> {
  const found: Array<{ path: string; name: string }> = [];
  walk(template as JsonValue, base, 0, (name, path) => {
    found.push({ path, name });
    return null;
  });
  return found;
}

function walk(
  node: JsonValue,
  path: string,
  depth: number,
  lookup: (name: string, path: string) => JsonValue,
): JsonValue {
  if (depth > MAX_DEPTH) return node;
  if (typeof node === "string") return fillString(node, path, lookup);
  if (Array.isArray(node)) return node.map((item, i) => walk(item, `${path}/${i}`, depth + 1, lookup));
  if (node && typeof node === "object") {
    const out: Record<string, JsonValue> = {};
    for (const [key, child] of Object.entries(node)) {
      // defineProperty, not assignment: a template key "__proto__" stays a plain key.
      Object.defineProperty(out, key, {
        value: walk(child, `${path}/${key.replace(/~/g, "~0").replace(/\//g, "~1")}`, depth + 1, lookup),
        enumerable: true,
        writable: true,
        configurable: true,
      });
    }
    return out;
  }
  return node;
}

function fillString(text: string, path: string, lookup: (name: string, path: string) => JsonValue): JsonValue {
  const whole = WHOLE.exec(text);
  if (whole) return structuredClone(lookup(whole[1]!, path));
  return text.replace(PLACEHOLDER, (_, name: string) => {
    const value = lookup(name, path);
    return typeof value === "string" ? value : JSON.stringify(value);
  });
}
