// Payload templates: {{ expression }} filled as JSON values by walking the
// parsed template, never by building JSON text. A string that is exactly one
// "{{…}}" becomes the expression's value with its type (a number stays a
// number); "-{{…}}" becomes the negated number, as HRIStudio's files write a
// negative speed; an expression inside a longer string is replaced by its
// value as text, in one pass, so a parameter whose text itself contains
// "{{x}}", quotes, braces, backslashes or newlines arrives exactly as given.
// A template that does not parse is never sent: it fails, naming itself and
// the character where reading stopped.
import { evaluate } from "./evaluate";
import { namesIn, parseExpression, type Node } from "./expression";
import type { JsonValue } from "./types";

const MAX_DEPTH = 64;
/** What a template nested past MAX_DEPTH is: never walked, so never sent unfilled either. */
const TOO_DEEP = `nested more than ${MAX_DEPTH} levels deep`;

export type FillResult = { ok: true; value: JsonValue } | { ok: false; path: string; reason: string };

type Part = string | { node: Node; at: number };
type Parts = { ok: true; parts: Part[] } | { ok: false; at: number; reason: string };

export function fillTemplate(template: JsonValue, parameters: Record<string, unknown>): FillResult {
  const lookup = (name: string) =>
    Object.hasOwn(parameters, name) ? (parameters[name] as JsonValue | undefined) : undefined;
  let failure: { path: string; reason: string } | null = null;
  const value = walk(template, "", 0, (text, path) => {
    if (failure) return null;
    const filled = text === null ? { ok: false as const, reason: TOO_DEEP } : fillString(text, lookup);
    if (filled.ok) return filled.value;
    failure = { path, reason: filled.reason };
    return null;
  });
  return failure ? { ok: false, ...(failure as { path: string; reason: string }) } : { ok: true, value };
}

/** Every parameter a template's expressions read, with the JSON Pointer of the string holding it. */
export function placeholders(template: unknown, base = ""): Array<{ path: string; name: string }> {
  const found: Array<{ path: string; name: string }> = [];
  walk(template as JsonValue, base, 0, (text, path) => {
    const split = text === null ? null : partsOf(text);
    if (split?.ok)
      for (const part of split.parts)
        if (typeof part !== "string") for (const name of namesIn(part.node)) found.push({ path, name });
    return null;
  });
  return found;
}

/** Every string of a template whose {{ }} do not parse, with the reason: such an action cannot run. */
export function templateProblems(template: unknown, base = ""): Array<{ path: string; reason: string }> {
  const found: Array<{ path: string; reason: string }> = [];
  walk(template as JsonValue, base, 0, (text, path) => {
    if (text === null) {
      found.push({ path, reason: `the template is ${TOO_DEEP}` });
      return null;
    }
    const split = partsOf(text);
    if (!split.ok) found.push({ path, reason: problem(text, split.at, split.reason) });
    return null;
  });
  return found;
}

function walk(
  node: JsonValue,
  path: string,
  depth: number,
  /** Called with each string, and with null for a part nested too deep to walk. */
  fill: (text: string | null, path: string) => JsonValue,
): JsonValue {
  if (depth > MAX_DEPTH) return fill(null, path);
  if (typeof node === "string") return fill(node, path);
  if (Array.isArray(node)) return node.map((item, i) => walk(item, `${path}/${i}`, depth + 1, fill));
  if (node && typeof node === "object") {
    const out: Record<string, JsonValue> = {};
    for (const [key, child] of Object.entries(node)) {
      // defineProperty, not assignment: a template key "__proto__" stays a plain key.
      Object.defineProperty(out, key, {
        value: walk(child, `${path}/${key.replace(/~/g, "~0").replace(/\//g, "~1")}`, depth + 1, fill),
        enumerable: true,
        writable: true,
        configurable: true,
      });
    }
    return out;
  }
  return node;
}

/** A template string's text and its expressions, each with the offset where its text starts. */
function partsOf(text: string): Parts {
  const parts: Part[] = [];
  let from = 0;
  for (let open = text.indexOf("{{"); open >= 0; open = text.indexOf("{{", from)) {
    const close = text.indexOf("}}", open + 2);
    if (close < 0) return { ok: false, at: open, reason: `"{{" is not closed by "}}"` };
    const parsed = parseExpression(text.slice(open + 2, close));
    if (!parsed.ok) return { ok: false, at: open + 2 + parsed.at, reason: parsed.reason };
    if (open > from) parts.push(text.slice(from, open));
    parts.push({ node: parsed.node, at: open + 2 });
    from = close + 2;
  }
  if (from < text.length) parts.push(text.slice(from));
  return { ok: true, parts };
}

function fillString(
  text: string,
  lookup: (name: string) => JsonValue | undefined,
): { ok: true; value: JsonValue } | { ok: false; reason: string } {
  const split = partsOf(text);
  if (!split.ok) return { ok: false, reason: problem(text, split.at, split.reason) };
  const values = valuesOf(text, split.parts, lookup);
  if (!values.ok) return values;
  const [first, second] = split.parts;
  const [, negated] = values.values;
  if (split.parts.length === 1 && typeof first !== "string")
    return { ok: true, value: structuredClone(values.values[0]!) };
  if (split.parts.length === 2 && first === "-" && typeof second !== "string" && typeof negated === "number")
    return { ok: true, value: negated === 0 ? 0 : -negated };
  return { ok: true, value: values.values.map(asText).join("") };
}

/**
 * A template string filled as text, each expression's value made text by
 * `encode` (a URL's parts are URL-encoded): the literal text is kept as written.
 */
export function fillText(
  text: string,
  parameters: Record<string, unknown>,
  encode: (text: string) => string,
): { ok: true; text: string } | { ok: false; reason: string } {
  const split = partsOf(text);
  if (!split.ok) return { ok: false, reason: problem(text, split.at, split.reason) };
  const lookup = (name: string) =>
    Object.hasOwn(parameters, name) ? (parameters[name] as JsonValue | undefined) : undefined;
  const values = valuesOf(text, split.parts, lookup);
  if (!values.ok) return values;
  const pieces = split.parts.map((part, i) => (typeof part === "string" ? part : encode(asText(values.values[i]!))));
  return { ok: true, text: pieces.join("") };
}

const asText = (v: JsonValue) => (typeof v === "string" ? v : JSON.stringify(v));

function valuesOf(
  text: string,
  parts: Part[],
  lookup: (name: string) => JsonValue | undefined,
): { ok: true; values: JsonValue[] } | { ok: false; reason: string } {
  const values: JsonValue[] = [];
  for (const part of parts) {
    if (typeof part === "string") {
      values.push(part);
      continue;
    }
    const result = evaluate(part.node, lookup);
    if (!result.ok)
      return {
        ok: false,
        // A missing parameter is named, and the path names where: the template adds nothing.
        reason: result.reason.startsWith("no value for")
          ? result.reason
          : problem(text, part.at + result.at, result.reason),
      };
    values.push(result.value);
  }
  return { ok: true, values };
}

/** Where a template went wrong, in words: the template itself (shortened) and the 1-based character. */
function problem(text: string, at: number, reason: string): string {
  const shown = text.length > 80 ? `${text.slice(0, 77)}...` : text;
  return `template ${JSON.stringify(shown)} at character ${at + 1}: ${reason}`;
}
