// Which of a plugin's actions this platform cannot carry out, and why. Such
// an action still loads (the file is not refused, as Node-RED keeps a node it
// cannot run and marks it unavailable); the designer and the portability
// report show it as unsupported with this reason, and it is never sent.
import { goalTypeOf, noGoalType } from "./goal";
import { maxTurnOf, transformOf } from "./transforms";
import { templateProblems } from "./template";
import { dispatchField, dispatchName, messageTemplate, reachableNames } from "./topic";
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
  return unavailable(plugin, action)?.reason ?? null;
}

export function unavailableActions(plugin: Pick<Plugin, "actions">): UnavailableAction[] {
  return plugin.actions.flatMap((action, i) => {
    const found = unavailable(plugin, action);
    return found ? [{ actionId: action.id, path: `/actions/${i}${found.path}`, reason: found.reason }] : [];
  });
}

/** The reason, and the JSON Pointer (within the action) of what gives it. */
function unavailable(plugin: Pick<Plugin, "actions">, action: PluginAction): { path: string; reason: string } | null {
  const ros2 = action.ros2;
  if (action.http) {
    const [bad] = templateProblems({ url: action.http.url, body: action.http.body ?? {} }, "/http");
    if (bad) return { path: bad.path, reason: `${bad.reason} (at ${bad.path.slice(1)})` };
  }
  if (!ros2) return null;
  const message = messageTemplate(ros2);
  const [bad] = templateProblems(message.template, message.at);
  if (bad) return { path: bad.path, reason: `${bad.reason} (at ${bad.path.slice(1)})` };
  const field = dispatchField(ros2);
  const reach = reachableNames(dispatchName(action)!, action.parameterSchema);
  if ("reason" in reach) return { path: `/ros2/${field}`, reason: `its ${field} ${reach.reason}` };
  if ("service" in ros2) return null;
  const mapping = ros2.payloadMapping;
  const at = (reason: string | null) => (reason ? { path: "/ros2", reason } : null);
  if (mapping.type === "transform") {
    const name = mapping.transformFn;
    const transform = transformOf(name);
    const path = "/ros2/payloadMapping/transformFn";
    if (!transform)
      return {
        path,
        reason: MISSING_BEHAVIOURS[name] ?? `it needs the transform "${name}", which this platform does not have`,
      };
    if (transform.kind === "motion" && maxTurnOf(plugin) === null)
      return {
        path,
        reason: `it turns at a fraction of the robot's top turning speed, and the plugin declares none (the "angular" maximum of a transformToTwist action)`,
      };
    if (transform.kind === "reading" && "action" in ros2)
      return { path, reason: `"${name}" reads a topic; it cannot be an action goal` };
  }
  if ("action" in ros2 && !ros2.actionType && !goalTypeOf(ros2.messageType)) return at(noGoalType(ros2));
  return null;
}
