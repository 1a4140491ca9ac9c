// loadPlugin(fileName, text): one plugin file in, either a plugin or every
// error we can find, each naming the file, the JSON Pointer and the reason.
// Pure: the caller reads the file. Nothing here throws on bad input.
import Ajv from "ajv";
import pluginSchema from "../../../plugins/plugin.schema.json";
import { plainErrors } from "./ajv-errors";
import { checkPlugin } from "./checks";
import { type LoadResult, type PluginError, pointer } from "./errors";
import { MAX_DEPTH, nestedTooDeep, parseJsonText, tooDeep } from "./json-text";
import type { Plugin } from "./types";

const ajv = new Ajv({ allErrors: true, strict: true, strictTypes: false, strictRequired: false });
const validatePlugin = ajv.compile(pluginSchema);

export function loadPlugin(file: string, text: string): LoadResult<Plugin> {
  const parsed = parseJson(file, text);
  if (!parsed.ok) return parsed;
  return checkDocument(file, parsed.value);
}

/**
 * For a document already parsed (a plugin fetched and decoded elsewhere).
 * One pass: the schema's errors and then every check a schema cannot make,
 * on each part the schema found sound, so an author sees every problem at once.
 */
export function checkDocument(file: string, document: unknown): LoadResult<Plugin> {
  // The schema's and our checks recurse: a document that did not come through parseJson is measured first.
  const deep = tooDeepAt(document);
  if (deep !== null)
    return {
      ok: false,
      errors: [{ file, path: deep, code: "too_deep", reason: nestedTooDeep }],
    };
  const schemaErrors = validatePlugin(document)
    ? []
    : plainErrors(validatePlugin.errors).map(
        (e): PluginError => ({ file, path: e.path, code: "schema", reason: e.reason }),
      );
  const broken = (at: string) => schemaErrors.some((e) => e.path === at || e.path.startsWith(`${at}/`));
  const errors = soundActions(document)
    ? [...schemaErrors, ...checkPlugin(file, document as Plugin, broken)]
    : schemaErrors;
  return errors.length ? { ok: false, errors } : { ok: true, value: document as Plugin };
}

/** The JSON Pointer of the first list or object deeper than MAX_DEPTH, or null; a loop, not recursion. */
function tooDeepAt(document: unknown): string | null {
  const pending: Array<{ value: unknown; at: string; depth: number }> = [{ value: document, at: "", depth: 0 }];
  for (let next = pending.pop(); next; next = pending.pop()) {
    const { value, at, depth } = next;
    if (typeof value !== "object" || value === null) continue;
    if (depth >= MAX_DEPTH) return at;
    for (const [key, inner] of Object.entries(value))
      pending.push({ value: inner, at: at + pointer(key), depth: depth + 1 });
  }
  return null;
}

/** Whether the document has a list of actions the checks can walk, even if some of them are broken. */
function soundActions(document: unknown): boolean {
  return typeof document === "object" && document !== null && Array.isArray((document as Plugin).actions);
}

export function parseJson(file: string, text: string): LoadResult<unknown> {
  const deep = tooDeep(text);
  if (deep) return { ok: false, errors: [{ file, path: "", code: "too_deep", reason: nestedTooDeep, ...deep }] };
  const parsed = parseJsonText(text);
  if (parsed.ok) return { ok: true, value: parsed.value };
  return {
    ok: false,
    errors: [
      {
        file,
        path: "",
        code: "invalid_json",
        reason: `invalid JSON: ${parsed.reason}`,
        line: parsed.line,
        column: parsed.column,
      },
    ],
  };
}
