// Where a step leads: the one reading of a step's "after" that the trial
// engine, the designer's checks, its flow map and the rehearsal preview share.
import type { After, TimeLimit, TrialProtocol } from "./document";

type Steps = TrialProtocol["steps"];

/** A step's way on when its actions are done and no branch took the trial elsewhere. */
export type Exit = { to: "step"; index: number } | { to: "end" } | { to: "missing"; stepId: string };

export function exitOf(steps: Steps, index: number): Exit {
  return exitBy(steps, index, steps[index]?.after ?? { to: "next" });
}

/** Where `after`, read from the step at `index`, leads: a step's own way on, or its time limit's. */
export function exitBy(steps: Steps, index: number, after: After): Exit {
  if (after.to === "end") return { to: "end" };
  if (after.to === "next") return index + 1 < steps.length ? { to: "step", index: index + 1 } : { to: "end" };
  const target = steps.findIndex((s) => s.id === after.stepId);
  return target < 0 ? { to: "missing", stepId: after.stepId } : { to: "step", index: target };
}

/** Where a step leads, in words that follow "leads to": `"Goodbye"`, "the end of the trial". */
export function describeExit(steps: Steps, index: number): string {
  const exit = exitOf(steps, index);
  if (exit.to === "end") return "the end of the trial";
  if (exit.to === "missing") return "a step that is no longer in the experiment";
  const step = steps[exit.index]!;
  return step.name.trim() ? `"${step.name.trim()}"` : `step ${exit.index + 1}`;
}

/** A step's time limits: its own, then its questions' ("no answer in …"). */
export function timeLimitsOf(step: Steps[number]): TimeLimit[] {
  const limits = [step.timeLimit, ...step.actions.map((a) => (a.type === "record_answer" ? a.timeLimit : undefined))];
  return limits.filter((limit) => limit !== undefined);
}
