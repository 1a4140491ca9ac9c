// Reading the protocol the way the engine walks it.
import type { ProtocolAction, TrialProtocol, TrialState } from "./types";

export function findStep(protocol: TrialProtocol, stepId: string | null) {
  const index = protocol.steps.findIndex((s) => s.id === stepId);
  return index < 0 ? null : { step: protocol.steps[index]!, index };
}

export function findAction(protocol: TrialProtocol, actionId: string) {
  for (const step of protocol.steps) {
    const action = step.actions.find((a) => a.id === actionId);
    if (action) return { step, action };
  }
  return null;
}

/**
 * The next scripted unit of the current step: its first waiting action, with
 * the actions right after it that share its parallel group (they start together).
 */
export function nextUnit(protocol: TrialProtocol, state: TrialState): ProtocolAction[] {
  const current = findStep(protocol, state.currentStepId);
  if (!current) return [];
  const actions = current.step.actions;
  const first = actions.findIndex((a) => state.actions[a.id]?.status === "waiting");
  if (first < 0) return [];
  const unit = [actions[first]!];
  const group = actions[first]!.parallelGroup;
  for (let i = first + 1; group && i < actions.length && actions[i]!.parallelGroup === group; i++) {
    if (state.actions[actions[i]!.id]?.status === "waiting") unit.push(actions[i]!);
  }
  return unit;
}

export interface AnswerOption {
  id: string;
  label: string;
}

export function answerOptions(action: ProtocolAction): AnswerOption[] {
  const options = action.parameters.options;
  return Array.isArray(options) ? (options as AnswerOption[]) : [];
}

/** Where a branch sends the trial for an answer, if anywhere. */
export function branchTarget(branch: ProtocolAction, optionId: string): string | null {
  const targets = branch.parameters.targets as Record<string, unknown> | undefined;
  const target = targets?.[optionId];
  return typeof target === "string" ? target : null;
}
