// loadPlugin(fileName, text): one plugin file in, either a plugin or every
// error we can find, each naming the file, the JSON Pointer and the reason.
// Pure: the caller reads the file. Nothing here throws on bad input.
import Ajv from "ajv";
import pluginSchema from "../../../plugins/plugin.schema.json";
import { plainErrors } from "./ajv-errors";
import { checkPlugin } from "./checks";
import type { LoadResult, PluginError } from "./errors";
import { parseJsonText } from "./json-text";
import type { Plugin } from "./types";

const ajv = new Ajv({ allErrors: true, strict: true, strictTypes: false, strictRequired: false });
const validatePlugin = ajv.compile(pluginSchema);

export function loadPlugin(file: string, text: string): LoadResult<Plugin> {
  const parsed = parseJson(file, text);
  if (!parsed.ok) return parsed;
  return checkDocument(file, parsed.value);
}

/** For a document already parsed (a plugin fetched and decoded elsewhere). */
export function checkDocument(file: string, document: unknown): LoadResult<Plugin> {
  if (!validatePlugin(document)) {
    const errors = plainErrors(validatePlugin.errors).map(
      (e): PluginError => ({ file, path: e.path, code: "schema", reason: e.reason }),
    );
    return { ok: false, errors };
  }
  const plugin = document as Plugin;
  const errors = checkPlugin(file, plugin);
  return errors.length ? { ok: false, errors } : { ok: true, value: plugin };
}

export function parseJson(file: string, text: string): LoadResult<unknown> {
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
