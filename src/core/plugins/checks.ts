// What the JSON Schema cannot say: ids unique, parameter schemas usable,
// placeholders that exist, abstract bindings that point at real actions and
// real parameters. Parts the schema already found broken are skipped (their
// error is reported), so every other part is still checked in the same pass.
// A transform we do not have is no error: the action loads as unsupported
// (availability.ts).
import { pointer, type PluginError, type PluginErrorCode } from "./errors";
import { checkEvents } from "./event-checks";
import { checkValue, compileParameterSchema } from "./parameters";
import { placeholders } from "./template";
import { dispatchField, dispatchName, messageTemplate, nameParameters } from "./topic";
import type { AbstractBinding, Plugin, PluginAction } from "./types";
import { abstractAction } from "./vocabulary";

/** Whether the schema found the part at this JSON Pointer broken. */
export type Broken = (at: string) => boolean;

export function checkPlugin(file: string, plugin: Plugin, broken: Broken = () => false): PluginError[] {
  const errors: PluginError[] = [];
  const add = (path: string, code: PluginErrorCode, reason: string) => errors.push({ file, path, code, reason });
  const seen = new Map<string, number>();
  plugin.actions.forEach((action, i) => {
    if (broken(pointer("actions", i))) {
      if (typeof action?.id === "string" && !seen.has(action.id)) seen.set(action.id, i);
      return;
    }
    const earlier = seen.get(action.id);
    if (earlier !== undefined)
      add(
        pointer("actions", i, "id"),
        "duplicate_action",
        `action id "${action.id}" is already used by /actions/${earlier}`,
      );
    else seen.set(action.id, i);
    checkAction(action, pointer("actions", i), add);
  });
  checkAbstract(plugin, add, broken);
  errors.push(...checkEvents(file, plugin, broken));
  (plugin.halt ?? []).forEach((id, i) => {
    if (!seen.has(id))
      add(
        pointer("halt", i),
        "bad_binding",
        `an emergency stop would send "${id}", which is not an action of this plugin`,
      );
  });
  return errors;
}

type Add = (path: string, code: PluginErrorCode, reason: string) => void;

function checkAction(action: PluginAction, at: string, add: Add) {
  const schema = action.parameterSchema;
  try {
    compileParameterSchema(schema);
  } catch (error) {
    add(`${at}/parameterSchema`, "bad_parameter_schema", (error as Error).message);
    return;
  }
  for (const [k, name] of (schema.required ?? []).entries()) {
    if (!Object.hasOwn(schema.properties, name))
      add(`${at}/parameterSchema/required/${k}`, "bad_parameter_schema", `requires "${name}", which is not a property`);
  }
  for (const [name, property] of Object.entries(schema.properties)) {
    const here = `${at}/parameterSchema${pointer("properties", name)}`;
    const { minimum, maximum } = property as { minimum?: number; maximum?: number };
    if (minimum !== undefined && maximum !== undefined && minimum > maximum) {
      add(`${here}/maximum`, "bad_parameter_schema", `maximum ${maximum} is below minimum ${minimum}`);
    }
    if (property.default !== undefined) {
      const problem = checkValue(property, property.default);
      if (problem)
        add(`${here}/default`, "bad_parameter_schema", `default ${JSON.stringify(property.default)} ${problem}`);
    }
  }
  const ros2 = action.ros2;
  if (ros2) {
    const known = (name: string) => Object.hasOwn(schema.properties, name);
    const message = messageTemplate(ros2);
    for (const p of placeholders(message.template, `${at}${message.at}`)) {
      if (!known(p.name))
        add(p.path, "unknown_placeholder", `{{${p.name}}} names no parameter of action "${action.id}"`);
    }
    const field = dispatchField(ros2);
    for (const name of nameParameters(dispatchName(action)!)) {
      if (!known(name))
        add(`${at}/ros2/${field}`, "unknown_placeholder", `{${name}} names no parameter of action "${action.id}"`);
    }
  }
  if (action.http) {
    for (const p of placeholders({ url: action.http.url, body: action.http.body ?? {} }, `${at}/http`)) {
      if (!Object.hasOwn(schema.properties, p.name))
        add(p.path, "unknown_placeholder", `{{${p.name}}} names no parameter of action "${action.id}"`);
    }
  }
}

function checkAbstract(plugin: Plugin, add: Add, broken: Broken) {
  const declared = broken("/unsupported") ? [] : (plugin.unsupported ?? []);
  const unsupported = new Set(declared.map((u) => u.action));
  declared.forEach((u, i) => {
    if (!abstractAction(u.action))
      add(pointer("unsupported", i, "action"), "unknown_abstract_action", `"${u.action}" is not an abstract action`);
  });
  if (broken("/abstract")) return;
  for (const [id, value] of Object.entries(plugin.abstract ?? {})) {
    const vocabulary = abstractAction(id);
    if (!vocabulary) {
      add(pointer("abstract", id), "unknown_abstract_action", `"${id}" is not an abstract action`);
      continue;
    }
    if (unsupported.has(id))
      add(pointer("abstract", id), "bad_binding", `"${id}" is both mapped and listed as unsupported`);
    const bindings: AbstractBinding[] = Array.isArray(value) ? value : [value];
    bindings.forEach((binding, n) => {
      const at = Array.isArray(value) ? pointer("abstract", id, n) : pointer("abstract", id);
      const index = plugin.actions.findIndex((a) => a?.id === binding.action);
      if (index < 0) return add(`${at}/action`, "bad_binding", `no action "${binding.action}" in this plugin`);
      const target = plugin.actions[index]!;
      if (broken(pointer("actions", index))) return;
      for (const name of Object.keys(binding.parameters ?? {})) {
        if (!Object.hasOwn(target.parameterSchema.properties, name))
          add(
            `${at}/parameters${pointer(name)}`,
            "bad_binding",
            `"${name}" is not a parameter of action "${target.id}"`,
          );
      }
      for (const p of placeholders(binding.parameters ?? {}, `${at}/parameters`)) {
        if (!Object.hasOwn(vocabulary.parameterSchema.properties, p.name))
          add(p.path, "unknown_placeholder", `{{${p.name}}} is not a parameter of abstract action "${id}"`);
      }
      for (const name of Object.keys(binding.when ?? {})) {
        if (!Object.hasOwn(vocabulary.parameterSchema.properties, name))
          add(`${at}/when${pointer(name)}`, "bad_binding", `"${name}" is not a parameter of abstract action "${id}"`);
      }
    });
  }
}
