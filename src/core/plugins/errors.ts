// One catalogue of plugin error codes, shared by the loader, the UI, the logs
// and docs/plugins.md. Every error names the file, the JSON path and a reason.

export const PLUGIN_ERROR_CODES = {
  invalid_json: "The file is not valid JSON.",
  schema: "The file does not match the plugin format.",
  duplicate_action: "Two actions share an id.",
  bad_parameter_schema: "An action's parameterSchema is not usable.",
  unknown_placeholder:
    "A placeholder (a payload's {{…}}, or a {part} of a topic or service name) names no parameter of its action.",
  bad_binding: "An abstract binding refers to something that does not exist.",
  unknown_abstract_action: "The plugin maps an abstract action that is not in the vocabulary.",
  bad_event:
    "An event the robot senses cannot be watched: its id is taken, its topic is templated, its message type is unknown, or its condition reads no such field.",
  duplicate_robot: "Two plugin files declare the same robotId.",
  unreadable: "The file could not be read.",
  too_large: "The file is larger than a plugin file may be; reading stopped at the limit.",
  too_deep: "The file nests lists and objects deeper than a plugin file may.",
} as const;

export type PluginErrorCode = keyof typeof PLUGIN_ERROR_CODES;

export interface PluginError {
  file: string;
  /** JSON Pointer into the file ("" is the whole document). */
  path: string;
  code: PluginErrorCode;
  reason: string;
  /** For invalid JSON: where the parser stopped, 1-based. */
  line?: number;
  column?: number;
}

export type LoadResult<T> = { ok: true; value: T } | { ok: false; errors: PluginError[] };

export function pointer(...segments: Array<string | number>): string {
  return segments.map((s) => "/" + String(s).replace(/~/g, "~0").replace(/\//g, "~1")).join("");
}

export function formatPluginError(error: PluginError): string {
  const where = error.line ? `${error.file}:${error.line}:${error.column}` : `${error.file} at ${error.path || "/"}`;
  return `${where}: ${error.reason}`;
}
