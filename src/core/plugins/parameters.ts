// Validating action parameters against an action's parameterSchema, with
// messages that name the parameter. Compiled validators are cached by the
// schema's content, not its object: plugins are read afresh for each
// portability check or publish, and ajv keeps every schema object it ever
// compiled, so a cache by object would compile (and hold) a copy per call.
import Ajv, { type ErrorObject, type ValidateFunction } from "ajv";
import { plainReason } from "./ajv-errors";
import type { ParameterSchema } from "./types";

// Not strict: HRIStudio files may carry UI hints (placeholder, step...) in
// their parameter schemas; the plugin schema already checks the keywords we use.
const ajv = new Ajv({ allErrors: true, strict: false });
const compiled = new Map<string, ValidateFunction>();

export interface ParameterProblem {
  parameter: string;
  message: string;
}

/** Compiles each distinct schema once; throws with ajv's reason if the schema is not usable. */
export function compileParameterSchema(schema: ParameterSchema | object): ValidateFunction {
  const key = JSON.stringify(schema);
  let validate = compiled.get(key);
  if (!validate) {
    validate = ajv.compile(schema);
    compiled.set(key, validate);
  }
  return validate;
}

/** Checks one value against one property's schema; for a parameter's default. */
export function checkValue(propertySchema: object, value: unknown): string | null {
  const validate = compileParameterSchema(propertySchema);
  if (validate(value)) return null;
  return (validate.errors ?? []).map(plainReason).join(", and ");
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
      if (error.keyword === "additionalProperties" && error.instancePath === "") continue; // reported above
      const params = error.params as Record<string, unknown>;
      const name =
        error.keyword === "required" && error.instancePath === ""
          ? String(params.missingProperty)
          : (error.instancePath.split("/")[1] ?? "");
      problems.push({ parameter: name, message: describe(error, name, schema) });
    }
  }
  return problems;
}

// The form shows a parameter by its title, so a problem names it that way:
// "Seconds" must be at most 3600; inside a list, "Answer" (number 2 in "Answers").
function describe(error: ErrorObject, name: string, schema: ParameterSchema): string {
  if (error.keyword === "required" && error.instancePath === "")
    return `${quoted(name, schema.properties[name])} is required`;
  const [, , ...inside] = error.instancePath.split("/");
  let property: unknown = schema.properties[name];
  let subject = quoted(name, property);
  for (const segment of inside) {
    const number = /^\d+$/.test(segment);
    const within = subject;
    property = field(property, number ? "items" : "properties", segment);
    subject = number ? `number ${Number(segment) + 1} in ${within}` : `${quoted(segment, property)} (${within})`;
  }
  if (error.keyword !== "required") return `${subject} ${plainReason(error)}`;
  const missing = String((error.params as { missingProperty: unknown }).missingProperty);
  return `${subject} needs ${quoted(missing, field(property, "properties", missing))}`;
}

function field(schema: unknown, kind: "items" | "properties", key: string): unknown {
  const s = schema as { items?: unknown; properties?: Record<string, unknown> } | undefined;
  return kind === "items" ? s?.items : s?.properties?.[key];
}

function quoted(name: string, property: unknown): string {
  const title = (property as { title?: unknown } | undefined)?.title;
  return `"${typeof title === "string" && title ? title : name}"`;
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
