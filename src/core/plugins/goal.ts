// A ROS 2 action goal from HRIStudio's dispatch block, which names the
// action (`"action": "/navigate_to_pose"`) and the goal's message
// (`messageType`) but not the action's type, which rosbridge needs to send it.
// A plugin may name it (`actionType`: the message is then the whole goal);
// otherwise the goal's message must be one of those below, each the goal of
// the one standard action HRIStudio's files mean by it.
import type { JsonObject, JsonValue } from "./types";

interface KnownGoal {
  actionType: string;
  goal: (message: JsonObject) => JsonValue;
}

const KNOWN_GOALS: Record<string, KnownGoal> = {
  // Nav2's NavigateToPose: {pose, behavior_tree}; an empty tree is Nav2's default.
  "geometry_msgs/msg/PoseStamped": {
    actionType: "nav2_msgs/action/NavigateToPose",
    goal: (pose) => ({ pose, behavior_tree: "" }),
  },
};

export type ActionGoal = { ok: true; actionType: string; goal: JsonValue } | { ok: false; reason: string };

export function actionGoal(
  ros2: { action: string; actionType?: string; messageType: string },
  message: JsonObject,
): ActionGoal {
  if (ros2.actionType) return { ok: true, actionType: ros2.actionType, goal: message };
  const known = goalTypeOf(ros2.messageType);
  if (!known) return { ok: false, reason: noGoalType(ros2) };
  return { ok: true, actionType: known.actionType, goal: known.goal(message) };
}

export const goalTypeOf = (messageType: string): KnownGoal | undefined =>
  Object.hasOwn(KNOWN_GOALS, messageType) ? KNOWN_GOALS[messageType] : undefined;

export function noGoalType(ros2: { action: string; messageType: string }): string {
  return `it sends a goal to the ROS 2 action ${ros2.action}, but its plugin names no actionType and its goal message ${ros2.messageType} is not one whose action we know`;
}
