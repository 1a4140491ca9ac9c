// An experiment action's `type` is either an abstract action id ("say",
// "wave") or a robot-specific action written "<robotId>.<actionId>"
// ("nao6-ros2.play_animation_bow"). Ids never contain a dot, so the first dot
// separates robot and action. Anything else is a control block of the trial
// engine (record_answer, branch, ...) or unknown.
import { CONTROL_TYPES } from "../trial/types";
import { abstractAction } from "./vocabulary";

export type ActionType =
  | { kind: "abstract"; id: string }
  | { kind: "robot"; robotId: string; actionId: string }
  | { kind: "control"; id: string }
  | { kind: "unknown"; type: string };

export function parseActionType(type: string): ActionType {
  const dot = type.indexOf(".");
  if (dot > 0 && dot < type.length - 1 && !type.includes(".", dot + 1)) {
    return { kind: "robot", robotId: type.slice(0, dot), actionId: type.slice(dot + 1) };
  }
  // pause is both: the runtime runs it, and the vocabulary documents it.
  if ((CONTROL_TYPES as readonly string[]).includes(type) && type !== "pause") return { kind: "control", id: type };
  if (abstractAction(type)) return { kind: "abstract", id: type };
  return { kind: "unknown", type };
}

export function robotActionType(robotId: string, actionId: string): string {
  return `${robotId}.${actionId}`;
}
