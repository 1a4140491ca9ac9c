// Reading and changing a designer draft, for the commands (model.ts): every
// change makes a new object and leaves the draft it was given as it was, so
// undo keeps the drafts before.
import { actionSchema, experimentFields, type StepVariant, stepSchema } from "../protocol/document";
import type { DesignAction, DesignDraft, DesignStep } from "./types";

/** What a command refuses, in words for the researcher. */
export class DesignerError extends Error {}

// The fields the declaration names, read from it: a field added there is kept
// by draftFrom, so reaches the snapshot and its hash, with nothing else to change.
const EXPERIMENT_KEYS = Object.keys(experimentFields.shape) as Array<keyof Omit<DesignDraft, "steps">>;
const STEP_KEYS = Object.keys(stepSchema.shape) as Array<keyof DesignStep>;
const ACTION_KEYS = Object.keys(actionSchema.shape) as Array<keyof DesignAction>;

/** The named fields of `value` that are set. */
function declared<T extends object, K extends keyof T>(value: T, keys: K[]): Pick<T, K> {
  const out = {} as Pick<T, K>;
  for (const key of keys) if (value[key] !== undefined) out[key] = value[key];
  return out;
}

/** The draft inside a stored design (which also carries positions, times, revision...). */
export function draftFrom(design: DesignDraft): DesignDraft {
  return {
    ...declared(design, EXPERIMENT_KEYS),
    steps: design.steps.map((s) => ({
      ...declared(s, STEP_KEYS),
      after: s.after ?? { to: "next" },
      actions: s.actions.map((a) => {
        const { note, ...action } = declared(a, ACTION_KEYS);
        // A note left empty is no note: a design without notes hashes as it did before notes.
        return note ? { ...action, note } : action;
      }),
    })),
  };
}

// ---- reading a draft ----

export function locateStep(draft: DesignDraft, stepId: string) {
  const index = draft.steps.findIndex((s) => s.id === stepId);
  if (index < 0) throw new DesignerError("That step is no longer in the experiment.");
  return { step: draft.steps[index]!, index };
}

export function locateAction(draft: DesignDraft, actionId: string) {
  for (const [stepIndex, step] of draft.steps.entries()) {
    const index = step.actions.findIndex((a) => a.id === actionId);
    if (index >= 0) return { step, stepIndex, action: step.actions[index]!, index };
  }
  throw new DesignerError("That action is no longer in the experiment.");
}

// ---- writing a draft (always a new object, never in place) ----

export function replaceStep(draft: DesignDraft, stepId: string, change: (s: DesignStep) => DesignStep): DesignDraft {
  return { ...draft, steps: draft.steps.map((s) => (s.id === stepId ? withoutLoneGroups(change(s)) : s)) };
}

/** A group of one is no group: an action left alone by an edit runs on its own again. */
export function withoutLoneGroups<T extends { actions: Array<{ parallelGroup: string | null }> }>(part: T): T {
  const count = new Map<string, number>();
  for (const a of part.actions) if (a.parallelGroup) count.set(a.parallelGroup, (count.get(a.parallelGroup) ?? 0) + 1);
  if (![...count.values()].includes(1)) return part;
  return {
    ...part,
    actions: part.actions.map((a) =>
      a.parallelGroup && count.get(a.parallelGroup) === 1 ? { ...a, parallelGroup: null } : a,
    ),
  };
}

/** The step's actions in `condition`, changed where one of them is `actionId`. */
export function replaceStepVariant(
  draft: DesignDraft,
  stepId: string,
  condition: string,
  actionId: string,
  change: (actions: StepVariant["actions"]) => StepVariant["actions"],
): DesignDraft {
  const variant = locateStep(draft, stepId).step.variants?.[condition];
  if (!variant) throw new DesignerError(`This step has no actions of its own in "${condition}".`);
  if (!variant.actions.some((a) => a.id === actionId))
    throw new DesignerError(`That action is no longer in this step's actions in "${condition}".`);
  return replaceStep(draft, stepId, (s) => ({
    ...s,
    variants: { ...s.variants, [condition]: withoutLoneGroups({ actions: change(variant.actions) }) },
  }));
}

export function replaceAction(
  draft: DesignDraft,
  actionId: string,
  change: (a: DesignAction) => DesignAction,
): DesignDraft {
  const { step } = locateAction(draft, actionId);
  return replaceStep(draft, step.id, (s) => ({
    ...s,
    actions: s.actions.map((a) => (a.id === actionId ? change(a) : a)),
  }));
}

export function clampIndex(index: number, length: number) {
  return Math.max(0, Math.min(Math.trunc(index), length));
}

export function move<T>(list: T[], from: number, to: number): T[] {
  const out = [...list];
  const [item] = out.splice(from, 1);
  out.splice(clampIndex(to, out.length), 0, item!);
  return out;
}

/** Leaving a group's neighbours behind would split it: an action that moves goes alone. */
export function leaveGroup(action: DesignAction): DesignAction {
  return action.parallelGroup ? { ...action, parallelGroup: null } : action;
}
