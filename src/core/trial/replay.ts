// A finished trial's robot commands, scheduled again: what the robot was sent,
// in the order it was sent, at the times the log says, from any point and at
// any speed. Pure: the runtime sends the schedule to the simulated robot.
//
// The time of a command is its `action.dispatched` event: the runtime hands the
// message to the robot's socket and only then logs "dispatched", with nothing
// in between, so that event is the log's closest record of when the robot
// received it (`action.requested` comes one database commit earlier). Its
// order is the order of those events, which is the order the messages left.
import { outgoingFor, resolveAction, type Outgoing, type Plugin, type PluginAction } from "../plugins";
import { CONTROL_TYPES, type TrialEvent } from "./types";

export const REPLAY_SPEEDS = [0.5, 1, 2] as const;

export interface ReplayCommand {
  /** When to send it: ms after the replay starts, at the replay's speed. */
  atMs: number;
  /** When it was sent in the trial (ms from t0). */
  trialMs: number;
  actionId: string;
  /** The plugin action and parameters that made the message, for the transport to send again. */
  action: PluginAction;
  parameters: Record<string, unknown>;
  /** What the simulated robot receives: a topic message, a service call, an action goal, a turn and its stop, or a topic read. */
  message: Exclude<Outgoing, { kind: "ssh" | "none" }>;
}

export interface ReplaySchedule {
  commands: ReplayCommand[];
  /** Commands of the trial a replay cannot send again over rosbridge, and why. */
  skipped: Array<{ actionId: string; trialMs: number; reason: string }>;
  /** The trial's last moment (ms from t0): where a replay from the start would end. */
  endMs: number;
}

const CONTROL = new Set<string>(CONTROL_TYPES);

export function replaySchedule(
  plugin: Plugin,
  events: TrialEvent[],
  { fromMs = 0, speed = 1 }: { fromMs?: number; speed?: number } = {},
): ReplaySchedule {
  // An action's request, as it was when dispatched: a step entered again requests its actions again.
  const requested = new Map<string, Extract<TrialEvent, { type: "action.requested" }>>();
  const commands: ReplayCommand[] = [];
  const skipped: ReplaySchedule["skipped"] = [];
  for (const event of [...events].sort((a, b) => a.seq - b.seq)) {
    if (event.type === "action.requested") requested.set(event.actionId, event);
    if (event.type !== "action.dispatched" || event.relMs === null || event.relMs < fromMs) continue;
    const request = requested.get(event.actionId);
    if (!request || CONTROL.has(request.actionType)) continue;
    const skip = (reason: string) => skipped.push({ actionId: event.actionId, trialMs: event.relMs!, reason });
    if (plugin.transport === "http" || plugin.transport === "ssh") {
      skip(`${plugin.name} was sent this over ${plugin.transport.toUpperCase()}, not rosbridge`);
      continue;
    }
    const resolved = resolveAction(plugin, request.actionType, request.parameters);
    if (resolved.status !== "supported") {
      skip(`${plugin.name} no longer resolves "${request.actionType}" as it did`);
      continue;
    }
    const message = outgoingFor(resolved.action, resolved.parameters, plugin);
    if (message.kind === "ssh") skip(`"${resolved.action.name}" went to the robot over SSH, not rosbridge`);
    else if (message.kind === "none") skip(message.reason);
    else
      commands.push({
        atMs: (event.relMs - fromMs) / speed,
        trialMs: event.relMs,
        actionId: event.actionId,
        action: resolved.action,
        parameters: resolved.parameters,
        message,
      });
  }
  const endMs = events.reduce((end, e) => Math.max(end, e.relMs ?? 0), 0);
  return { commands, skipped, endMs };
}
