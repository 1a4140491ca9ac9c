// Where a step leads: the one reading of a step's "after" that the trial
// engine, the designer's checks, its flow map and the rehearsal preview share.
import type { After, Loop, TimeLimit, TrialProtocol } from "./document";

type Steps = TrialProtocol["steps"];

/** A step's way on when its actions are done and no branch took the trial elsewhere. */
export type Exit = { to: "step"; index: number } | { to: "end" } | { to: "missing"; stepId: string };

/** `taken`: how many times this trial has gone back by the step's loop, if its "after" is one. */
export function exitOf(steps: Steps, index: number, taken = 0): Exit {
  return exitBy(steps, index, steps[index]?.after ?? { to: "next" }, taken);
}

/**
 * Where `after`, read from the step at `index`, leads: a step's own way on, or
 * its time limit's. A loop leads back while it has been taken fewer than its
 * `times` (`taken` so far), then where its "onward" leads.
 */
export function exitBy(steps: Steps, index: number, after: After, taken = 0): Exit {
  if (after.to === "end") return { to: "end" };
  if (after.to === "next") return index + 1 < steps.length ? { to: "step", index: index + 1 } : { to: "end" };
  if (after.to === "again" && taken >= after.times) return exitBy(steps, index, after.onward);
  const target = steps.findIndex((s) => s.id === after.stepId);
  return target < 0 ? { to: "missing", stepId: after.stepId } : { to: "step", index: target };
}

/** Every way `after` may lead: a loop's way back (with its bound) and its "onward"; otherwise the one. */
export function waysBy(steps: Steps, index: number, after: After): Array<{ exit: Exit; loop?: Loop }> {
  if (after.to !== "again") return [{ exit: exitBy(steps, index, after) }];
  return [{ exit: exitBy(steps, index, after), loop: after }, { exit: exitBy(steps, index, after.onward) }];
}

/** Where a step leads, in words that follow "leads to": `"Goodbye"`, "the end of the trial". */
export function describeExit(steps: Steps, index: number): string {
  const after = steps[index]?.after;
  const [back, then] = waysBy(steps, index, after ?? { to: "next" }).map((way) => describe(steps, way.exit));
  return after?.to === "again" ? `${back} again, at most ${timesWords(after.times)}, then ${then}` : back!;
}

/** "once", "2 times": how often a loop may go back. */
export function timesWords(times: number): string {
  return times === 1 ? "once" : `${times} times`;
}

function describe(steps: Steps, exit: Exit): string {
  if (exit.to === "end") return "the end of the trial";
  if (exit.to === "missing") return "a step that is no longer in the experiment";
  const step = steps[exit.index]!;
  return step.name.trim() ? `"${step.name.trim()}"` : `step ${exit.index + 1}`;
}

/** The blocks that may have a time limit of their own: a question ("no answer in …") and a wait ("nothing sensed in …"). */
export const TIMED_BLOCKS: ReadonlySet<string> = new Set(["record_answer", "wait_for"]);

/** A step's time limits: its own, then its questions' and waits'. */
export function timeLimitsOf(step: Steps[number]): TimeLimit[] {
  const limits = [step.timeLimit, ...step.actions.map((a) => (TIMED_BLOCKS.has(a.type) ? a.timeLimit : undefined))];
  return limits.filter((limit) => limit !== undefined);
}

/** One event a "Wait for" block waits for: its own id, the robot's event (a RobotEvent id), and where it leads. */
export interface AwaitedEvent {
  id: string;
  event: string;
  after: After;
}

/** The events a "Wait for" block lists, as far as they are well formed (the designer's checks report the rest). */
export function awaitedEvents(action: { type: string; parameters: Record<string, unknown> }): AwaitedEvent[] {
  const events = action.type === "wait_for" ? action.parameters.events : undefined;
  if (!Array.isArray(events)) return [];
  return events.flatMap((e: unknown) => {
    const { id, event, after } = (e && typeof e === "object" ? e : {}) as Record<string, unknown>;
    const to = (after as { to?: unknown } | undefined)?.to;
    if (typeof id !== "string" || typeof event !== "string" || typeof to !== "string") return [];
    return [{ id, event, after: after as After }];
  });
}
