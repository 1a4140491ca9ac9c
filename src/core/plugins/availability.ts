// Which of a plugin's actions this platform cannot carry out, and why. Such
// an action still loads (the file is not refused, as Node-RED keeps a node it
// cannot run and marks it unavailable); the designer and the portability
// report show it as unsupported with this reason, and it is never sent.
import { goalTypeOf, noGoalType } from "./goal";
import { maxTurnOf, transformOf } from "./transforms";
import type { Plugin, PluginAction } from "./types";

/** Behaviours HRIStudio's files name that need more than sending a message, and what they need. */
const MISSING_BEHAVIOURS: Record<string, string> = {
  wallFollowing:
    "it follows a wall by steering from the laser scanner in a closed loop on the robot, and this platform runs no such controller",
  captureAndSaveImage:
    "it saves a picture from the robot's camera to a file, and this platform has no way to store the robot's pictures",
  collectLaserScan:
    "it records laser scans for a while and saves them, and this platform has no way to store the robot's scans",
};

export interface UnavailableAction {
  actionId: string;
  /** JSON Pointer to what makes it unavailable. */
  path: string;
  reason: string;
}

/** Why this platform cannot carry out the action, in words that follow "cannot run: "; null when it can. */
export function unavailableReason(plugin: Pick<Plugin, "actions">, action: PluginAction): string | null {
  const ros2 = action.ros2;
  if (!ros2 || !("payloadMapping" in ros2)) return null;
  const mapping = ros2.payloadMapping;
  if (mapping.type === "transform") {
    const name = mapping.transformFn;
    const transform = transformOf(name);
    if (!transform)
      return MISSING_BEHAVIOURS[name] ?? `it needs the transform "${name}", which this platform does not have`;
    if (transform.kind === "motion" && maxTurnOf(plugin) === null)
      return `it turns at a fraction of the robot's top turning speed, and the plugin declares none (the "angular" maximum of a transformToTwist action)`;
    if (transform.kind === "reading" && "action" in ros2) return `"${name}" reads a topic; it cannot be an action goal`;
  }
  if ("action" in ros2 && !ros2.actionType && !goalTypeOf(ros2.messageType)) return noGoalType(ros2);
  return null;
}

export function unavailableActions(plugin: Pick<Plugin, "actions">): UnavailableAction[] {
  return plugin.actions.flatMap((action, i) => {
    const reason = unavailableReason(plugin, action);
    if (!reason) return [];
    const mapping = action.ros2 && "payloadMapping" in action.ros2 ? action.ros2.payloadMapping : null;
    const path = mapping?.type === "transform" ? `/actions/${i}/ros2/payloadMapping/transformFn` : `/actions/${i}/ros2`;
    return [{ actionId: action.id, path, reason }];
  });
}
