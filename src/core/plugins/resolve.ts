// From an experiment action ({type, parameters}) to the plugin action that
// performs it and that action's parameters, or the reason it cannot run.
import { parseActionType } from "./action-type";
import { unavailableReason } from "./availability";
import { validateParameters, withDefaults, type ParameterProblem } from "./parameters";
import { fillTemplate } from "./template";
import type { AbstractBinding, JsonObject, Plugin, PluginAction } from "./types";
import { abstractAction } from "./vocabulary";

export type Resolution =
  | { status: "runtime" }
  /** No robot action does it: the wizard's browser does (play audio on a robot that cannot). */
  | { status: "browser" }
  | { status: "supported"; action: PluginAction; parameters: Record<string, unknown> }
  | { status: "unsupported"; reason: string }
  | { status: "parameter_problems"; problems: ParameterProblem[]; action?: PluginAction };

export function resolveAction(plugin: Plugin, type: string, parameters: unknown): Resolution {
  const parsed = parseActionType(type);
  switch (parsed.kind) {
    case "control":
      return { status: "runtime" };
    case "unknown":
      return { status: "unsupported", reason: `"${type}" is neither an abstract action nor "<robotId>.<actionId>"` };
    case "robot": {
      if (parsed.robotId !== plugin.robotId) {
        return { status: "unsupported", reason: `written for robot "${parsed.robotId}", not "${plugin.robotId}"` };
      }
      const action = plugin.actions.find((a) => a.id === parsed.actionId);
      if (!action) return { status: "unsupported", reason: `${plugin.robotId} has no action "${parsed.actionId}"` };
      return unavailable(plugin, action) ?? checked(action, parameters);
    }
    case "abstract":
      return resolveAbstract(plugin, parsed.id, parameters);
  }
}

function resolveAbstract(plugin: Plugin, id: string, parameters: unknown): Resolution {
  const vocabulary = abstractAction(id)!;
  const problems = validateParameters(vocabulary.parameterSchema, parameters);
  if (problems.length) return { status: "parameter_problems", problems };
  if (vocabulary.runtime) return { status: "runtime" };
  const declared = plugin.unsupported?.find((u) => u.action === id);
  const value = plugin.abstract?.[id];
  if ((declared || !value) && vocabulary.browserFallback) return { status: "browser" };
  if (declared) return { status: "unsupported", reason: declared.reason };
  if (!value) return { status: "unsupported", reason: `${plugin.robotId} does not map "${id}"` };
  const given = withDefaults(vocabulary.parameterSchema, parameters as Record<string, unknown>);
  const bindings: AbstractBinding[] = Array.isArray(value) ? value : [value];
  const binding = bindings.find((b) => Object.entries(b.when ?? {}).every(([k, v]) => given[k] === v));
  if (!binding) return { status: "parameter_problems", problems: unmatched(bindings, given) };
  const action = plugin.actions.find((a) => a.id === binding.action)!;
  const cannot = unavailable(plugin, action);
  if (cannot) return cannot;
  // An abstract parameter left out (an optional speed) leaves the robot's default.
  const present = Object.fromEntries(
    Object.entries(binding.parameters ?? {}).filter(([, t]) => !mentionsMissing(t, given)),
  );
  const filled = fillTemplate(present as JsonObject, given);
  if (!filled.ok) return { status: "parameter_problems", problems: [{ parameter: "", message: filled.reason }] };
  return checked(action, filled.value);
}

/** An action the plugin declares but this platform cannot carry out (availability.ts). */
function unavailable(plugin: Plugin, action: PluginAction): Resolution | null {
  const reason = unavailableReason(plugin, action);
  return reason
    ? { status: "unsupported", reason: `${plugin.robotId}'s "${action.name}" cannot run: ${reason}` }
    : null;
}

function checked(action: PluginAction, parameters: unknown): Resolution {
  const problems = validateParameters(action.parameterSchema, parameters);
  if (problems.length) return { status: "parameter_problems", problems, action };
  return {
    status: "supported",
    action,
    parameters: withDefaults(action.parameterSchema, parameters as Record<string, unknown>),
  };
}

function mentionsMissing(template: unknown, given: Record<string, unknown>): boolean {
  const match = typeof template === "string" ? /^\{\{\s*(\w+)\s*\}\}$/.exec(template) : null;
  return !!match && given[match[1]!] === undefined;
}

function unmatched(bindings: AbstractBinding[], given: Record<string, unknown>): ParameterProblem[] {
  const names = [...new Set(bindings.flatMap((b) => Object.keys(b.when ?? {})))];
  return names.map((name) => {
    const supported = [...new Set(bindings.map((b) => b.when?.[name]).filter((v) => v !== undefined))];
    return {
      parameter: name,
      message: `"${name}" ${JSON.stringify(given[name])} is not supported by this robot (supported: ${supported.map((v) => JSON.stringify(v)).join(", ")})`,
    };
  });
}
