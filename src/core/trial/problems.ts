// Why an action was not done, in words the wizard can act on, folded from the
// trial's events: the reason a failure was logged with, or a timeout said
// plainly. Sending the action again clears it. The wizard's view shows it
// beside the action's red badge.
import type { TrialEvent } from "./types";

export const TIMED_OUT =
  "The robot did not report it done within the action's time limit: check that the robot is on and connected.";

export function actionProblems(events: readonly TrialEvent[]): Record<string, string> {
  const problems: Record<string, string> = {};
  for (const event of events) {
    if (event.type === "action.failed" || event.type === "action.not_sent" || event.type === "action.unknown")
      problems[event.actionId] = sentence(event.reason);
    else if (event.type === "action.completed") delete problems[event.actionId];
    else if (event.type === "action.timed_out") problems[event.actionId] = TIMED_OUT;
    else if (event.type === "action.requested") delete problems[event.actionId];
  }
  return problems;
}

const sentence = (reason: string) => {
  const text = reason.trim() || "no reason was given";
  return `${text[0]!.toUpperCase()}${text.slice(1)}${/[.!?]$/.test(text) ? "" : "."}`;
};
