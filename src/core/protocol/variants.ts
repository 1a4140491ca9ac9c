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
 * The rest of the document (a snapshot's experiment and version) is kept.
 */
export function inCondition<P extends { steps: Step[] }>(protocol: P, condition: string | null): InCondition<P> {
  return {
    ...protocol,
    steps: protocol.steps.map(({ variants, actions, ...step }) => {
      const own = condition === null ? undefined : variants?.[condition];
      return {
        ...step,
        actions: own
          ? own.actions.map((action) => ({ ...action, variant: condition! }))
          : actions.map((action) => actionIn(action, condition)),
      };
    }),
  } as InCondition<P>;
}

type StepOf<P extends { steps: Step[] }> = P["steps"][number];

/** A protocol as one condition runs it: its fields as they were, its steps and actions without variants, each action maybe marked. */
export type InCondition<P extends { steps: Step[] }> = Omit<P, "steps"> & {
  steps: Array<
    Omit<StepOf<P>, "actions" | "variants"> & {
      actions: Array<Omit<StepOf<P>["actions"][number], "variants"> & { variant?: string }>;
    }
  >;
};

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

type Checked = { id: string; type: string; parameters?: Record<string, unknown> };

/**
 * Every action of a step as some condition may run it: its own actions, each
 * action's variants, and the step's variants' actions, each variant with the
 * condition it is for. What the portability report checks, so no condition
 * meets an action its robot cannot do.
 */
export function everyVariant<A extends Checked>(step: {
  actions: ReadonlyArray<A & { variants?: Record<string, { type?: string; parameters: Record<string, unknown> }> }>;
  variants?: Record<string, { actions: ReadonlyArray<Checked> }>;
}): Array<Checked & { condition?: string }> {
  return [
    ...step.actions.flatMap(({ variants, ...action }) => [
      action,
      ...Object.entries(variants ?? {}).map(([condition, v]) => ({
        id: action.id,
        type: v.type ?? action.type,
        parameters: v.parameters,
        condition,
      })),
    ]),
    ...Object.entries(step.variants ?? {}).flatMap(([condition, v]) => v.actions.map((a) => ({ ...a, condition }))),
  ];
}

/**
 * Action ids used in more than one step, a step's variants counted as the
 * step: a trial keeps each action's state by its id, so an action of one step
 * must not share it with another step's. (A step's variant may reuse the
 * step's own ids: only one of them runs.)
 */
export function idsInTwoSteps(
  steps: ReadonlyArray<{
    id?: string;
    actions: ReadonlyArray<{ id?: string }>;
    variants?: Record<string, { actions: ReadonlyArray<{ id: string }> }>;
  }>,
): string[] {
  const stepOf = new Map<string, number>();
  const repeated = new Set<string>();
  steps.forEach((step, index) => {
    const ids = new Set([
      ...step.actions.flatMap((a) => (a.id ? [a.id] : [])),
      ...Object.values(step.variants ?? {}).flatMap((v) => v.actions.map((a) => a.id)),
    ]);
    for (const id of ids) {
      if (stepOf.has(id) && stepOf.get(id) !== index) repeated.add(id);
      stepOf.set(id, index);
    }
  });
  return [...repeated];
}
