// Validating action parameters against an action's parameterSchema, with
// messages that name the parameter. Compiled validators are cached per schema
// object, so a plugin's schemas compile once when it loads.
import Ajv, { type ErrorObject, type ValidateFunction } from "ajv";
import type { ParameterSchema } from "./types";

// Not strict: HRIStudio files may carry UI hints (placeholder, step...) in
// their parameter schemas; the plugin schema already checks the keywords we use.
const ajv = new Ajv({ allErrors: true, strict: false });
const ARTICLE: Record<string, string> = { integer: "an integer", object: "an object", array: "a list" };
const compiled = new WeakMap<object, ValidateFunction>();

export interface ParameterProblem {
  parameter: string;
  message: string;
}

/** Compiles once; throws with ajv's reason if the schema is not usable. */
export function compileParameterSchema(schema: ParameterSchema | object): ValidateFunction {
  let validate = compiled.get(schema);
  if (!validate) {
    validate = ajv.compile(schema);
    compiled.set(schema, validate);
  }
  return validate;
}

/** Checks one value against one property's schema; for a parameter's default. */
export function checkValue(propertySchema: object, value: unknown): string | null {
  const validate = ajv.compile(propertySchema);
  if (validate(value)) return null;
  return ajv.errorsText(validate.errors, { dataVar: "value" }).replace(/^value /, "");
}

export function validateParameters(schema: ParameterSchema, parameters: unknown): ParameterProblem[] {
  if (!parameters || typeof parameters !== "object" || Array.isArray(parameters)) {
    return [{ parameter: "", message: "parameters must be an object of named values" }];
  }
  const problems: ParameterProblem[] = [];
  // A misspelt parameter would otherwise be ignored silently on the robot.
  for (const name of Object.keys(parameters)) {
    if (!Object.hasOwn(schema.properties, name)) {
      problems.push({ parameter: name, message: `"${name}" is not a parameter of this action` });
    }
  }
  const validate = compileParameterSchema(schema);
  if (!validate(parameters)) {
    for (const error of validate.errors ?? []) {
      if (error.keyword === "additionalProperties") continue; // reported above
      const params = error.params as Record<string, unknown>;
      const name =
        error.keyword === "required" ? String(params.missingProperty) : (error.instancePath.split("/")[1] ?? "");
      problems.push({ parameter: name, message: describe(error, name) });
    }
  }
  return problems;
}

function describe(error: ErrorObject, name: string): string {
  const params = error.params as Record<string, unknown>;
  switch (error.keyword) {
    case "required":
      return `"${name}" is required`;
    case "type":
      return `"${name}" must be ${ARTICLE[String(params.type)] ?? `a ${String(params.type)}`}`;
    case "enum":
      return `"${name}" must be one of ${(params.allowedValues as unknown[]).map((v) => JSON.stringify(v)).join(", ")}`;
    case "minLength":
      if (params.limit === 1) return `"${name}" must not be empty`;
  }
  const inside = error.instancePath
    .split("/")
    .slice(2)
    .map((s) => `[${s}]`)
    .join("");
  return `"${name}"${inside} ${error.message}`;
}

/** The parameters with schema defaults filled in where a value is absent. */
export function withDefaults(schema: ParameterSchema, parameters: Record<string, unknown>): Record<string, unknown> {
  const out: Record<string, unknown> = { ...parameters };
  for (const [name, property] of Object.entries(schema.properties)) {
    const fallback = property.default;
    // Only objects need a copy; the designer validates every action on each edit.
    if (out[name] === undefined && fallback !== undefined)
      out[name] = typeof fallback === "object" && fallback !== null ? structuredClone(fallback) : fallback;
  }
  return out;
}
