// Following a step's way on, loops included: "go back to <step>, at most K
// times, then …". The count is read from the log (the fold keeps how many
// times each loop went back), so a trial resumed after a crash goes round
// exactly as many times as it would have.
import type { After, Loop, Onward } from "../protocol/document";
import { type Exit, exitBy, exitOf } from "../protocol/flow";
import type { EngineEvent, TrialProtocol, TrialState } from "./types";

/** How the trial moves on by an "after" that is no loop: the wizard's next, or a time limit running out. */
type Via = "next" | "timeout";

/**
 * A loop's name in the log: the "after" it belongs to, a step's own way on,
 * its time limit's, or a question's time limit's.
 */
export function loopName(stepId: string, limit?: { of: "step" } | { of: "answer"; actionId: string }): string {
  if (!limit) return `after:${stepId}`;
  return limit.of === "step" ? `time:${stepId}` : `time:${stepId}:${limit.actionId}`;
}

/** Every loop of a protocol, by its name, with the step it leaves from and, for a time limit's, its seconds. */
export function loopsOf(
  protocol: TrialProtocol,
): Array<{ name: string; stepId: string; loop: Loop; seconds?: number }> {
  return protocol.steps.flatMap((step) => {
    const afters: Array<[string, After | undefined, number?]> = [
      [loopName(step.id), step.after],
      [loopName(step.id, { of: "step" }), step.timeLimit?.after, step.timeLimit?.seconds],
      ...step.actions.map((a): [string, After | undefined, number?] => [
        loopName(step.id, { of: "answer", actionId: a.id }),
        a.type === "record_answer" ? a.timeLimit?.after : undefined,
        a.timeLimit?.seconds,
      ]),
    ];
    return afters.flatMap(([name, after, seconds]) =>
      after?.to === "again" ? [{ name, stepId: step.id, loop: after, ...(seconds ? { seconds } : {}) }] : [],
    );
  });
}

/** How many times the loop `name` has gone back in this trial. */
export function timesTaken(state: TrialState, name: string): number {
  return state.loops[name] ?? 0;
}

/** Where the step at `index` leads once its actions are done, as this trial has gone round its loop so far. */
export function exitNow(protocol: TrialProtocol, state: TrialState, index: number): Exit {
  return exitOf(protocol.steps, index, timesTaken(state, loopName(protocol.steps[index]!.id)));
}

/**
 * The events of leaving the step at `index` by `after`: back round a loop
 * (the step entered again, logged with the loop's name), a loop's bound
 * reached and then its "onward", another step, or the trial's end. A step that
 * is gone (a rehearsal's draft only: it cannot be published) ends the trial.
 */
export function follow(
  protocol: TrialProtocol,
  state: TrialState,
  index: number,
  after: After,
  name: string,
  via: Via,
): EngineEvent[] {
  if (after.to !== "again") return leave(protocol, index, after, { via });
  const taken = timesTaken(state, name);
  if (taken < after.times) {
    const back = exitBy(protocol.steps, index, after, taken);
    if (back.to !== "step") return [{ type: "trial.completed" }];
    return [{ type: "step.entered", stepId: protocol.steps[back.index]!.id, via: "loop", loop: name }];
  }
  const stepId = protocol.steps[index]!.id;
  return [
    { type: "loop.bound_reached", stepId, loop: name, times: after.times },
    ...leave(protocol, index, after.onward, { via: "loop_bound", loop: name }),
  ];
}

function leave(
  protocol: TrialProtocol,
  index: number,
  after: Onward,
  entered: { via: Via | "loop_bound"; loop?: string },
): EngineEvent[] {
  const exit = exitBy(protocol.steps, index, after);
  if (exit.to !== "step") return [{ type: "trial.completed" }];
  return [{ type: "step.entered", stepId: protocol.steps[exit.index]!.id, ...entered }];
}
