// One experiment, run differently per condition: an action or a whole step may
// carry a variant per condition (document.ts, "variants", by condition name).
// A trial runs the protocol as its condition runs it; a condition without a
// variant runs the shared design.
import type { DesignAction, DesignStep, TrialProtocol } from "./document";

type Action = TrialProtocol["steps"][number]["actions"][number] & Pick<DesignAction, "variants">;
type Step = Omit<TrialProtocol["steps"][number], "actions"> &
  Pick<DesignStep, "variants"> & { actions: Array<Action & { variants?: DesignAction["variants"] }> };

/**
 * The protocol as a trial in `condition` (a condition's name) runs it: each
 * step's and action's variant for it in place of the shared one, marked with
 * the condition it is for (what exports name); null runs the shared design.
 * No variant is left in it: the trial, and the wizard's page, see one protocol.
 */
export function inCondition(protocol: { steps: Step[] }, condition: string | null): TrialProtocol {
  return {
    steps: protocol.steps.map(({ variants, actions, ...step }) => {
      const own = condition === null ? undefined : variants?.[condition];
      return {
        ...step,
        actions: own
          ? own.actions.map((action) => ({ ...action, variant: condition! }))
          : actions.map((action) => actionIn(action, condition)),
      };
    }),
  };
}

function actionIn(
  { variants, ...action }: Action,
  condition: string | null,
): TrialProtocol["steps"][number]["actions"][number] {
  const own = condition === null ? undefined : variants?.[condition];
  return own ? { ...action, type: own.type ?? action.type, parameters: own.parameters, variant: condition! } : action;
}

/** Where variants are and which conditions have one: a step's, or one action's of it. */
export interface Varied {
  stepId: string;
  actionId?: string;
  conditions: string[];
}

/** Every step and action that varies by condition, with the conditions it names, in the design's order. */
export function variedParts(steps: ReadonlyArray<Pick<DesignStep, "id" | "variants" | "actions">>): Varied[] {
  return steps.flatMap((step) => [
    ...(step.variants ? [{ stepId: step.id, conditions: Object.keys(step.variants) }] : []),
    ...step.actions.flatMap((action) =>
      action.variants ? [{ stepId: step.id, actionId: action.id, conditions: Object.keys(action.variants) }] : [],
    ),
  ]);
}

/** Each varied part with the conditions of `conditions` that have no variant there (they run the shared one). */
export function lackingVariants(steps: Parameters<typeof variedParts>[0], conditions: readonly string[]): Varied[] {
  return variedParts(steps).flatMap((part) => {
    const lacking = conditions.filter((c) => !part.conditions.includes(c));
    return lacking.length ? [{ ...part, conditions: lacking }] : [];
  });
}

type Named = { variants?: Record<string, unknown> };

/** The condition names variants are kept under that are none of `conditions`, in the design's order. */
export function unknownConditions(
  steps: ReadonlyArray<Named & { actions: ReadonlyArray<Named> }>,
  conditions: readonly string[],
): string[] {
  const named = new Set(
    steps.flatMap((step) => [step, ...step.actions].flatMap((part) => Object.keys(part.variants ?? {}))),
  );
  return [...named].filter((name) => !conditions.includes(name));
}
