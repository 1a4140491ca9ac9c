// The names a trial's events are about, for every place that shows or exports
// them: a step by its name, an action by its display name (scripted ones from
// the protocol, unscripted ones from the request that sent them).
import { actionName, type ActionNames } from "@/core/designer/action-name";
import type { TrialEvent, TrialProtocol } from "@/core/trial";

export interface TrialNames {
  step(stepId: string | null | undefined): string | undefined;
  action(actionId: string | null | undefined): string | undefined;
  /** The step's and the action's names an event carries ids of, and the condition whose variant of the action ran. */
  of(event: object): { stepName?: string; actionName?: string; variant?: string };
}

type Named = { stepId?: string | null; actionId?: string; actionType?: string; parameters?: Record<string, unknown> };

/**
 * The names of a trial's steps and actions. `learn` takes more of its events
 * (in log order). An unscripted action's events all follow its request (the
 * engine refuses a report on an action never requested), so a log too large to
 * hold is named a page at a time, each page learnt before it is named: every
 * event gets the name the whole log would give it, in one pass over the log.
 */
export function trialNames(
  protocol: TrialProtocol,
  events: readonly object[],
  names?: ActionNames,
): TrialNames & { learn(events: readonly object[]): void } {
  const steps = new Map(protocol.steps.map((s) => [s.id, s.name]));
  const actions = new Map(protocol.steps.flatMap((s) => s.actions.map((a) => [a.id, actionName(a, names)])));
  // A protocol as its trial's condition ran it marks each action of a condition's variant (core/protocol/variants.ts).
  const variants = new Map(
    protocol.steps.flatMap((s) => s.actions.flatMap((a) => (a.variant === undefined ? [] : [[a.id, a.variant]]))),
  );
  const learn = (events: readonly object[]) => {
    for (const e of events as Array<TrialEvent & Named>)
      if (e.type === "action.requested" && e.actionId && !actions.has(e.actionId))
        actions.set(e.actionId, actionName({ type: e.actionType ?? "", parameters: e.parameters }, names));
  };
  learn(events);
  const step = (id: string | null | undefined) => (id ? steps.get(id) : undefined);
  const action = (id: string | null | undefined) => (id ? actions.get(id) : undefined);
  return {
    learn,
    step,
    action,
    of: (event) => {
      const { stepId, actionId } = event as Named;
      const stepName = step(stepId);
      const actionName = action(actionId);
      const variant = actionId ? variants.get(actionId) : undefined;
      return {
        ...(stepName !== undefined && { stepName }),
        ...(actionName !== undefined && { actionName }),
        ...(variant !== undefined && { variant }),
      };
    },
  };
}
