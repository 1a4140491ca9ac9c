// A plugin repository as HRIStudio publishes it: repository.json at the root
// and plugins/index.json listing the plugin file names.
import Ajv from "ajv";
import { plainErrors } from "./ajv-errors";
import type { LoadResult, PluginError } from "./errors";
import { parseJson } from "./load";
import type { PluginRepository } from "./types";

const ajv = new Ajv({ allErrors: true, strict: true });

const validateRepository = ajv.compile({
  type: "object",
  required: ["id", "name"],
  properties: {
    id: { type: "string", pattern: "^[a-z0-9][a-z0-9_-]*$" },
    name: { type: "string", minLength: 1 },
    trust: { enum: ["official", "verified", "community"] },
    pluginApiVersion: { type: "string", pattern: "^1\\.[0-9]+$" },
    urls: { type: "object", additionalProperties: { type: "string" } },
  },
});

// A plugin file name, never a path: a repository must not reach outside plugins/.
const validateIndex = ajv.compile({
  type: "array",
  uniqueItems: true,
  items: { type: "string", pattern: "^[A-Za-z0-9][A-Za-z0-9_.-]*\\.json$" },
});

export function parseRepository(file: string, text: string): LoadResult<PluginRepository> {
  return check(file, text, validateRepository, 'must be lower-case letters, digits, "-" or "_"');
}

export function parsePluginIndex(file: string, text: string): LoadResult<string[]> {
  return check(file, text, validateIndex, "must be a plugin file name ending in .json, without folders");
}

/** `patternReason` replaces ajv's regular expression, which means nothing to a researcher. */
function check<T>(
  file: string,
  text: string,
  validate: ReturnType<typeof ajv.compile>,
  patternReason: string,
): LoadResult<T> {
  const parsed = parseJson(file, text);
  if (!parsed.ok) return parsed;
  if (validate(parsed.value)) return { ok: true, value: parsed.value as T };
  const errors = plainErrors(validate.errors).map(
    (e): PluginError => ({
      file,
      path: e.path,
      code: "schema",
      reason: e.reason.startsWith("must match the pattern") ? patternReason : e.reason,
    }),
  );
  return { ok: false, errors };
}
