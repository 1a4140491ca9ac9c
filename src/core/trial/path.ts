// The wizard's view of the way through: the steps this trial has taken and
// what comes next, instead of every step of every branch.
import { exitNow } from "./loops";
import { answerOptions, branchTarget, findStep } from "./protocol";
import type { TrialProtocol, TrialState } from "./types";

type Step = TrialProtocol["steps"][number];

export type Upcoming =
  | { kind: "step"; step: Step }
  | { kind: "answer"; routes: Array<{ label: string; step: Step | null }> }
  | { kind: "end" };

export function upcoming(protocol: TrialProtocol, state: TrialState): Upcoming {
  if (state.status === "completed" || state.status === "aborted") return { kind: "end" };
  const current = findStep(protocol, state.currentStepId);
  if (!current) return protocol.steps[0] ? { kind: "step", step: protocol.steps[0] } : { kind: "end" };
  const waiting = current.step.actions.filter((a) => state.actions[a.id]?.status === "waiting");
  if (waiting.some((a) => a.type === "end_trial")) return { kind: "end" };
  const branch = waiting.find((a) => a.type === "branch");
  const question = branch && current.step.actions[current.step.actions.indexOf(branch) - 1];
  if (branch && question?.type === "record_answer") {
    return {
      kind: "answer",
      routes: answerOptions(question).map((o) => ({
        label: o.label,
        step: findStep(protocol, branchTarget(branch, o.id))?.step ?? null,
      })),
    };
  }
  const exit = exitNow(protocol, state, current.index);
  return exit.to === "step" ? { kind: "step", step: protocol.steps[exit.index]! } : { kind: "end" };
}

/** The steps entered so far, in order, a step entered twice listed twice. */
export function pathTaken(protocol: TrialProtocol, state: TrialState): Step[] {
  return state.path.flatMap((id) => findStep(protocol, id)?.step ?? []);
}
