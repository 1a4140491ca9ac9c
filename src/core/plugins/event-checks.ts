// What the JSON Schema cannot say about the events a robot senses: ids
// unique, a topic that is one fixed name, a message type whose fields we
// know, and a condition that reads fields that message has, of the right
// kind. Each reason names the event, so an author knows which to fix.
import { type Field, fieldType, knownMessage } from "../robots/messages";
import { pointer, type PluginError } from "./errors";
import { nameParameters } from "./topic";
import type { Condition, FieldValue, Plugin, RobotEvent } from "./types";

type Add = (path: string, reason: string) => void;

export function checkEvents(file: string, plugin: Plugin, broken: (at: string) => boolean): PluginError[] {
  const errors: PluginError[] = [];
  const seen = new Map<string, number>();
  if (broken("/events") && !Array.isArray(plugin.events)) return errors;
  (plugin.events ?? []).forEach((event, i) => {
    if (broken(pointer("events", i))) return;
    const add: Add = (path, reason) =>
      errors.push({
        file,
        path: pointer("events", i) + path,
        code: "bad_event",
        reason: `event "${event.id}": ${reason}`,
      });
    const earlier = seen.get(event.id);
    if (earlier !== undefined) add("/id", `the id is already used by /events/${earlier}`);
    else seen.set(event.id, i);
    for (const problem of declarationProblems(event)) add(problem.at, problem.reason);
  });
  return errors;
}

/** Why an event cannot be watched as declared, each with its pointer under the event. */
export function declarationProblems(event: RobotEvent): Array<{ at: string; reason: string }> {
  const problems: Array<{ at: string; reason: string }> = [];
  if (nameParameters(event.topic).length)
    problems.push({
      at: "/topic",
      reason: `its topic ${event.topic} has {parameter} parts, but nothing fills an event's topic: name one topic`,
    });
  if (!knownMessage(event.messageType)) {
    problems.push({
      at: "/messageType",
      reason: `HRIStudio does not know the fields of ${event.messageType}, so its condition cannot be checked`,
    });
    return problems;
  }
  for (const [at, reason] of conditionProblems(event.messageType, event.when))
    problems.push({ at: `/when${at}`, reason });
  return problems;
}

const NUMBERS = /^(u?int(8|16|32|64)|float(32|64))$/;
const isNumber = (type: Field | null) => type !== null && NUMBERS.test(type);
const isScalar = (type: Field | null) => isNumber(type) || type === "string" || type === "bool";
const fits = (type: Field, value: FieldValue) =>
  typeof value === "number" ? isNumber(type) : typeof value === "boolean" ? type === "bool" : type === "string";

function conditionProblems(type: string, when: Condition): Array<[string, string]> {
  const problems: Array<[string, string]> = [];
  const field = (at: string, path: string, ok: (t: Field) => boolean, wanted: string) => {
    const found = fieldType(type, path);
    if (found === null) problems.push([at, `${type} has no field ${path}`]);
    else if (!ok(found)) problems.push([at, `${path} of ${type} is ${found}, not ${wanted}`]);
  };
  switch (when.kind) {
    case "pressed": {
      const compared = (at: string, path: string, value: FieldValue) =>
        field(at, path, (t) => isScalar(t) && fits(t, value), `a field ${JSON.stringify(value)} can be compared with`);
      compared("/field", when.field, when.equals);
      for (const [path, value] of Object.entries(when.where ?? {})) compared(pointer("where", path), path, value);
      break;
    }
    case "heard":
      field("/field", when.field, (t) => t === "string" || t === "string[]", "words (string or string[])");
      field("/confidenceField", when.confidenceField, (t) => isNumber(t.replace(/\[\]$/, "")), "confidences (numbers)");
      break;
    case "near":
      field("/field", when.field, (t) => isNumber(t.replace(/\[\]$/, "")), "a distance (a number or a list of them)");
      if (when.clearAbove < when.below)
        problems.push([
          "/clearAbove",
          `clearAbove (${when.clearAbove}) is less than below (${when.below}): nothing near would ever clear`,
        ]);
      break;
  }
  return problems;
}
