// The plugin types are checked against plugins/plugin.schema.json, the
// authority: every field the types name is in the schema, and every field of
// the schema is either typed or listed here as kept as written.
import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import type { AbstractBinding, Condition, ParameterSchema, Plugin, PluginAction, RobotEvent } from "./types";

/** The named keys of a type, without its index signature. */
type Named<T> = keyof { [K in keyof T as string extends K ? never : K]: T[K] };
type Fields<T> = { [K in Named<T>]-?: true };

// The compiler makes each list name exactly the type's fields: one missing or extra does not build.
const PLUGIN: Fields<Plugin> = {
  robotId: true,
  name: true,
  description: true,
  version: true,
  pluginApiVersion: true,
  trustLevel: true,
  category: true,
  capabilities: true,
  ros2Config: true,
  transport: true,
  actions: true,
  abstract: true,
  unsupported: true,
  stateTopics: true,
  camera: true,
  halt: true,
  events: true,
};
const ACTION: Fields<PluginAction> = {
  id: true,
  name: true,
  description: true,
  category: true,
  icon: true,
  timeout: true,
  retryable: true,
  parameterSchema: true,
  ros2: true,
  http: true,
  completion: true,
};
const PARAMETERS: Fields<ParameterSchema> = {
  type: true,
  properties: true,
  required: true,
  additionalProperties: true,
};
const BINDING: Fields<AbstractBinding> = { action: true, parameters: true, when: true };
const EVENT: Fields<RobotEvent> = {
  id: true,
  name: true,
  description: true,
  topic: true,
  messageType: true,
  throttleRate: true,
  when: true,
};
type Kind<K extends Condition["kind"]> = Fields<Extract<Condition, { kind: K }>>;
const PRESSED: Kind<"pressed"> = { kind: true, field: true, equals: true, where: true };
const HEARD: Kind<"heard"> = { kind: true, field: true, confidenceField: true, words: true, minConfidence: true };
const NEAR: Kind<"near"> = { kind: true, field: true, below: true, forMs: true, clearAbove: true };

/** Fields of the schema the code reads through `[extra: string]` or not at all: kept as the file wrote them. */
const KEPT_AS_WRITTEN = ["platform", "hriStudioVersion", "httpBaseUrl"];

const schema = JSON.parse(readFileSync("plugins/plugin.schema.json", "utf8")) as {
  properties: Record<string, { items?: { properties: Record<string, unknown> } }>;
  definitions: Record<
    string,
    {
      properties?: Record<string, unknown>;
      allOf?: Array<{ then: { properties: { kind: { const: string } } & Record<string, unknown> } }>;
    }
  >;
};
const keys = (o: object) => Object.keys(o).sort();

describe("plugin types against plugins/plugin.schema.json", () => {
  it.each([
    ["a plugin", keys(PLUGIN), keys(schema.properties).filter((k) => !KEPT_AS_WRITTEN.includes(k))],
    ["an action", keys(ACTION), keys(schema.definitions.action!.properties!)],
    ["a parameter schema", keys(PARAMETERS), keys(schema.definitions.parameterSchema!.properties!)],
    ["an abstract binding", keys(BINDING), keys(schema.definitions.binding!.properties!)],
    ["an event", keys(EVENT), keys(schema.properties.events!.items!.properties)],
    ...(
      [
        ["pressed", PRESSED],
        ["heard", HEARD],
        ["near", NEAR],
      ] as const
    ).map(([kind, fields]) => [
      `a "${kind}" condition`,
      keys(fields),
      keys(schema.definitions.condition!.allOf!.find((c) => c.then.properties.kind.const === kind)!.then.properties),
    ]),
  ])("%s has the schema's fields", (_what, typed, declared) => {
    expect(typed).toEqual(declared);
  });
});
