// The portability report: before a trial, every action of an experiment
// against one plugin: supported, unsupported (with the reason), or supported
// with parameter problems (each naming the parameter). Given this server's
// ways to the robot, an action none of them carries is unsupported here too.
import { awaitedEvents } from "../protocol/flow";
import type { ParameterProblem } from "./parameters";
import { unreachable, type Channels } from "./reach";
import { resolveAction } from "./resolve";
import { dispatchName, reachableNames } from "./topic";
import type { Plugin, PluginAction } from "./types";
import { finish, type Work } from "../work";
import { everyVariant } from "../protocol/variants";

/** The experiment shape the report reads: steps of typed actions, each with its variants per condition. */
export interface PortableExperiment {
  steps: Array<{
    id?: string;
    name?: string;
    actions: Array<{
      id: string;
      type: string;
      parameters?: Record<string, unknown>;
      variants?: Record<string, { type?: string; parameters: Record<string, unknown> }>;
    }>;
    variants?: Record<string, { actions: Array<{ id: string; type: string; parameters?: Record<string, unknown> }> }>;
  }>;
}

export type PortabilityStatus = "supported" | "unsupported" | "parameter_problems";

export interface ActionPortability {
  stepIndex: number;
  actionId: string;
  type: string;
  /** The condition whose variant this is; absent for the action every other condition runs. */
  condition?: string;
  status: PortabilityStatus;
  /** Who carries it out: the robot, the trial runtime (pause, branch...), or the wizard's browser (play audio). */
  by: "robot" | "runtime" | "browser";
  /** The plugin action that performs it, when there is one. */
  pluginAction?: string;
  reason?: string;
  problems: ParameterProblem[];
  /**
   * Every topic, service or ROS 2 action the robot action can send to, when
   * that is known before a trial: its name has no {parameter} parts, or only
   * parts whose parameter has a fixed set of values.
   */
  reaches?: string[];
}

export interface PortabilityReport {
  robotId: string;
  pluginVersion: string;
  portable: boolean;
  actions: ActionPortability[];
}

export function portability(experiment: PortableExperiment, plugin: Plugin, channels?: Channels): PortabilityReport {
  const actions = experiment.steps.flatMap((step, stepIndex) =>
    everyVariant(step).map((action): ActionPortability => {
      const base = {
        stepIndex,
        actionId: action.id,
        type: action.type,
        ...(action.condition !== undefined && { condition: action.condition }),
        problems: [] as ParameterProblem[],
      };
      const resolution = resolveAction(plugin, action.type, action.parameters ?? {});
      switch (resolution.status) {
        case "runtime": {
          // A "Wait for" runs in the runtime, on what the robot reports: each event it waits for must be one the robot senses.
          const events = awaitedEvents({ type: action.type, parameters: action.parameters ?? {} }).map((e) => e.event);
          const problems = eventProblems(events, plugin);
          if (problems.length) return { ...base, status: "unsupported", by: "runtime", reason: problems.join(" ") };
          return { ...base, status: "supported", by: "runtime" };
        }
        case "browser":
          return { ...base, status: "supported", by: "browser" };
        case "supported": {
          const pluginAction = resolution.action.id;
          const reason = channels && unreachable(plugin, resolution.action, channels);
          if (reason) return { ...base, status: "unsupported", by: "robot", pluginAction, reason };
          return { ...base, status: "supported", by: "robot", pluginAction, ...reachesOf(resolution.action) };
        }
        case "unsupported":
          return { ...base, status: "unsupported", by: "robot", reason: resolution.reason };
        case "parameter_problems":
          return {
            ...base,
            status: "parameter_problems",
            by: "robot",
            pluginAction: resolution.action?.id,
            problems: resolution.problems,
          };
      }
    }),
  );
  return {
    robotId: plugin.robotId,
    pluginVersion: plugin.version,
    portable: actions.every((a) => a.status === "supported"),
    actions,
  };
}

function reachesOf(action: PluginAction): { reaches?: string[] } {
  const name = dispatchName(action);
  const reach = name === null ? null : reachableNames(name, action.parameterSchema);
  return reach && "names" in reach ? { reaches: reach.names } : {};
}

/**
 * Why a trial of this protocol cannot start on a robot with this plugin: each
 * action of the protocol the plugin cannot do, with its step and reason, in
 * plain words; null when it can do them all.
 */
export function cannotStart(protocol: PortableExperiment, plugin: Plugin): string | null {
  return finish(checkingStart(protocol, plugin));
}

/** cannotStart as work that yields after each step, for the runtime to run in slices beside its other trials. */
export function* checkingStart(protocol: PortableExperiment, plugin: Plugin): Work<string | null> {
  const missing: ActionPortability[] = [];
  for (const [stepIndex, step] of protocol.steps.entries()) {
    const report = portability({ steps: [step] }, plugin);
    for (const a of report.actions) if (a.status === "unsupported") missing.push({ ...a, stepIndex });
    yield;
  }
  if (!missing.length) return null;
  const listed = missing.map((a) => {
    const step = protocol.steps[a.stepIndex]!;
    return `step ${a.stepIndex + 1}${step.name ? ` (${step.name})` : ""}, "${a.type}": ${a.reason}`;
  });
  const what = missing.length === 1 ? "an action" : `${missing.length} actions`;
  return `This trial cannot start: ${plugin.name} (plugin ${plugin.version}) cannot do ${what} of its protocol: ${listed.join("; ")}.`;
}

/**
 * Why the robot cannot report each of these events (the ids a "Wait for"
 * waits for): one plain reason per event the plugin does not declare; empty
 * when it can report them all.
 */
export function eventProblems(eventIds: readonly string[], plugin: Plugin): string[] {
  const declared = new Set((plugin.events ?? []).map((e) => e.id));
  const offered = [...declared].join(", ") || "none";
  return [...new Set(eventIds)]
    .filter((id) => !declared.has(id))
    .map((id) => `${plugin.name} (plugin ${plugin.version}) does not sense "${id}" (it senses: ${offered})`);
}
