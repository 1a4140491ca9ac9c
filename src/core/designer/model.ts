// The designer as a headless model: named commands over a draft, with undo
// and redo. The page only renders a draft and sends commands, so every edit a
// researcher can make is tested here without a browser.
import {
  type ActionVariant,
  actionSchema,
  experimentFields,
  type StepVariant,
  stepSchema,
  type TimeLimit,
} from "../protocol/document";
import type { DesignAction, DesignDraft, DesignStep, NewId, After } from "./types";
import { WAITS_FOR_CHOICE } from "./blocks";

export class DesignerError extends Error {}

export interface Command {
  /** What the undo button says: "Undo move action". */
  label: string;
  /** Typing is many commands; consecutive ones with the same key undo as one. */
  mergeKey?: string;
  apply(draft: DesignDraft, newId: NewId): DesignDraft;
}

export interface History {
  present: DesignDraft;
  past: Array<{ label: string; draft: DesignDraft; mergeKey?: string }>;
  future: Array<{ label: string; draft: DesignDraft }>;
}

const HISTORY_LIMIT = 200;

export function startHistory(draft: DesignDraft): History {
  return { present: draft, past: [], future: [] };
}

export function execute(history: History, command: Command, newId: NewId): History {
  const next = command.apply(history.present, newId);
  if (next === history.present) return history;
  const last = history.past.at(-1);
  if (command.mergeKey && last?.mergeKey === command.mergeKey && history.future.length === 0)
    return { ...history, present: next };
  const entry = { label: command.label, draft: history.present, mergeKey: command.mergeKey };
  return { present: next, past: [...history.past, entry].slice(-HISTORY_LIMIT), future: [] };
}

export function undo(history: History): History {
  const last = history.past.at(-1);
  if (!last) return history;
  return {
    present: last.draft,
    past: history.past.slice(0, -1),
    future: [{ label: last.label, draft: history.present }, ...history.future],
  };
}

export function redo(history: History): History {
  const [first, ...rest] = history.future;
  if (!first) return history;
  return {
    present: first.draft,
    past: [...history.past, { label: first.label, draft: history.present }],
    future: rest,
  };
}

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

function replaceStep(draft: DesignDraft, stepId: string, change: (s: DesignStep) => DesignStep): DesignDraft {
  return { ...draft, steps: draft.steps.map((s) => (s.id === stepId ? withoutLoneGroups(change(s)) : s)) };
}

/** A group of one is no group: an action left alone by an edit runs on its own again. */
function withoutLoneGroups<T extends { actions: Array<{ parallelGroup: string | null }> }>(part: T): T {
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
function replaceStepVariant(
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

function replaceAction(draft: DesignDraft, actionId: string, change: (a: DesignAction) => DesignAction): DesignDraft {
  const { step } = locateAction(draft, actionId);
  return replaceStep(draft, step.id, (s) => ({
    ...s,
    actions: s.actions.map((a) => (a.id === actionId ? change(a) : a)),
  }));
}

function clampIndex(index: number, length: number) {
  return Math.max(0, Math.min(Math.trunc(index), length));
}

function move<T>(list: T[], from: number, to: number): T[] {
  const out = [...list];
  const [item] = out.splice(from, 1);
  out.splice(clampIndex(to, out.length), 0, item!);
  return out;
}

/** Leaving a group's neighbours behind would split it: an action that moves goes alone. */
function leaveGroup(action: DesignAction): DesignAction {
  return action.parallelGroup ? { ...action, parallelGroup: null } : action;
}

// ---- the commands ----

export interface NewAction {
  type: string;
  name: string;
  parameters: Record<string, unknown>;
}

export const commands = {
  setDetails: (changes: Partial<Pick<DesignDraft, "name" | "description">>): Command => ({
    label: "rename experiment",
    mergeKey: `details:${Object.keys(changes).join()}`,
    apply: (d) => ({ ...d, ...changes }),
  }),

  setRobot: (robotId: string): Command => ({
    label: "change robot",
    apply: (d) => (d.robotId === robotId ? d : { ...d, robotId }),
  }),

  addStep: (name: string, index?: number, id?: string): Command => ({
    label: "add step",
    apply: (d, newId) => {
      const steps = [...d.steps];
      steps.splice(clampIndex(index ?? steps.length, steps.length), 0, {
        id: id ?? newId(),
        name,
        description: "",
        after: { to: "next" },
        actions: [],
      });
      return { ...d, steps };
    },
  }),

  updateStep: (stepId: string, changes: Partial<Pick<DesignStep, "name" | "description">>): Command => ({
    label: "edit step",
    mergeKey: `step:${stepId}:${Object.keys(changes).join()}`,
    apply: (d) => (locateStep(d, stepId), replaceStep(d, stepId, (s) => ({ ...s, ...changes }))),
  }),

  /** Where the step leads once its actions are done: the next step, a named step, or the end. */
  setAfter: (stepId: string, after: After): Command => ({
    label: "set where the step leads",
    apply: (d) => {
      locateStep(d, stepId);
      if (after.to === "step" || after.to === "again") locateStep(d, after.stepId);
      if (after.to === "again" && after.onward.to === "step") locateStep(d, after.onward.stepId);
      return replaceStep(d, stepId, (s) => ({ ...s, after }));
    },
  }),

  /** null: no time limit. */
  setStepTimeLimit: (stepId: string, limit: TimeLimit | null): Command => ({
    label: "set the step's time limit",
    mergeKey: `step-time-limit:${stepId}`,
    apply: (d) => replaceStep(d, stepId, ({ timeLimit: _, ...s }) => (limit ? { ...s, timeLimit: limit } : s)),
  }),

  removeStep: (stepId: string): Command => ({
    label: "delete step",
    apply: (d) => (locateStep(d, stepId), { ...d, steps: d.steps.filter((s) => s.id !== stepId) }),
  }),

  moveStep: (stepId: string, toIndex: number): Command => ({
    label: "move step",
    apply: (d) => {
      const { index } = locateStep(d, stepId);
      const to = clampIndex(toIndex, d.steps.length - 1);
      return index === to ? d : { ...d, steps: move(d.steps, index, to) };
    },
  }),

  addAction: (stepId: string, index: number, action: NewAction, id?: string): Command => ({
    label: `add ${action.name}`,
    apply: (d, newId) => {
      locateStep(d, stepId);
      return replaceStep(d, stepId, (s) => {
        const actions = [...s.actions];
        actions.splice(clampIndex(index, actions.length), 0, { id: id ?? newId(), ...action, parallelGroup: null });
        return { ...s, actions };
      });
    },
  }),

  removeAction: (actionId: string): Command => ({
    label: "delete action",
    apply: (d) => {
      const { step } = locateAction(d, actionId);
      return replaceStep(d, step.id, (s) => ({ ...s, actions: s.actions.filter((a) => a.id !== actionId) }));
    },
  }),

  /** Within its step or into another; `toIndex` counts the target step's actions without the moved one. */
  moveAction: (actionId: string, toStepId: string, toIndex: number): Command => ({
    label: "move action",
    apply: (d) => {
      const from = locateAction(d, actionId);
      const target = locateStep(d, toStepId);
      if (from.step.id === toStepId) {
        const to = clampIndex(toIndex, from.step.actions.length - 1);
        if (to === from.index) return d;
        const actions = from.step.actions.map((a) => (a.id === actionId ? leaveGroup(a) : a));
        return replaceStep(d, toStepId, (s) => ({ ...s, actions: move(actions, from.index, to) }));
      }
      const without = replaceStep(d, from.step.id, (s) => ({
        ...s,
        actions: s.actions.filter((a) => a.id !== actionId),
      }));
      return replaceStep(without, target.step.id, (s) => {
        const actions = [...s.actions];
        actions.splice(clampIndex(toIndex, actions.length), 0, leaveGroup(from.action));
        return { ...s, actions };
      });
    },
  }),

  renameAction: (actionId: string, name: string): Command => ({
    label: "rename action",
    mergeKey: `name:${actionId}`,
    apply: (d) => replaceAction(d, actionId, (a) => ({ ...a, name })),
  }),

  /** The note the wizard reads beside the action; an empty note is none. */
  setNote: (actionId: string, note: string): Command => ({
    label: "edit note for the wizard",
    mergeKey: `note:${actionId}`,
    apply: (d) => replaceAction(d, actionId, ({ note: _, ...a }) => (note.trim() ? { ...a, note } : a)),
  }),

  /** A question's "no answer in N s"; null: none. */
  setAnswerTimeLimit: (actionId: string, limit: TimeLimit | null): Command => ({
    label: "set the answer's time limit",
    mergeKey: `answer-time-limit:${actionId}`,
    apply: (d) => replaceAction(d, actionId, ({ timeLimit: _, ...a }) => (limit ? { ...a, timeLimit: limit } : a)),
  }),

  /** The action as `condition` runs it; null: that condition runs the shared action. The last one gone, none is left. */
  setVariant: (actionId: string, condition: string, variant: ActionVariant | null): Command => ({
    label: `vary for ${condition}`,
    mergeKey: `variant:${actionId}:${condition}`,
    apply: (d) =>
      replaceAction(d, actionId, ({ variants = {}, ...a }) => {
        const { [condition]: _, ...others } = variants;
        const next = variant ? { ...others, [condition]: variant } : others;
        return Object.keys(next).length ? { ...a, variants: next } : a;
      }),
  }),

  /**
   * The step's own actions in `condition`: own, a copy of the step's actions
   * with new ids (a trial keeps each action's state by id, and the copy is
   * another action), without variants of their own; not own, none, so that
   * condition runs the step's actions. The last one gone, none is left.
   */
  setStepVariant: (stepId: string, condition: string, own: boolean): Command => ({
    label: own ? `vary step for ${condition}` : `share step with ${condition}`,
    apply: (d, newId) => {
      if (own === Boolean(locateStep(d, stepId).step.variants?.[condition])) return d;
      return replaceStep(d, stepId, ({ variants = {}, ...s }) => {
        const { [condition]: _, ...others } = variants;
        if (own) return { ...s, variants: { ...others, [condition]: { actions: s.actions.map(copy) } } };
        return Object.keys(others).length ? { ...s, variants: others } : s;
      });
      function copy({ variants: _, ...action }: DesignAction): StepVariant["actions"][number] {
        return { ...action, id: newId() };
      }
    },
  }),

  /** A parameter of an action of the step's own in `condition`; `undefined` removes it. */
  setStepVariantParameter: (
    stepId: string,
    condition: string,
    actionId: string,
    parameter: string,
    value: unknown,
  ): Command => ({
    label: `set ${parameter} in ${condition}`,
    mergeKey: `step-variant-parameter:${stepId}:${condition}:${actionId}:${parameter}`,
    apply: (d) =>
      replaceStepVariant(d, stepId, condition, actionId, (actions) =>
        actions.map((a) => {
          if (a.id !== actionId) return a;
          const { [parameter]: _, ...parameters } = a.parameters;
          return { ...a, parameters: value === undefined ? parameters : { ...parameters, [parameter]: value } };
        }),
      ),
  }),

  /** Removes an action from the step's own in `condition` (the step's shared actions keep theirs). */
  removeStepVariantAction: (stepId: string, condition: string, actionId: string): Command => ({
    label: `delete action in ${condition}`,
    apply: (d) =>
      replaceStepVariant(d, stepId, condition, actionId, (actions) => actions.filter((a) => a.id !== actionId)),
  }),

  /** `undefined` removes the parameter, so the block's default applies. */
  setParameter: (actionId: string, parameter: string, value: unknown): Command => ({
    label: `set ${parameter}`,
    mergeKey: `parameter:${actionId}:${parameter}`,
    apply: (d) =>
      replaceAction(d, actionId, (a) => {
        const parameters = { ...a.parameters };
        if (value === undefined) delete parameters[parameter];
        else parameters[parameter] = value;
        return { ...a, parameters };
      }),
  }),

  /** Starts this action together with the one above it (joining that one's group), or on its own. */
  setRunTogether: (actionId: string, together: boolean): Command => ({
    label: together ? "run together" : "run on its own",
    apply: (d, newId) => {
      const { step, index, action } = locateAction(d, actionId);
      if (!together) {
        if (!action.parallelGroup) return d;
        // Actions below it stay grouped among themselves, under a new name.
        const below = step.actions.slice(index + 1);
        const rest = below.findIndex((a) => a.parallelGroup !== action.parallelGroup);
        const tail = rest < 0 ? below.length : rest;
        const renamed = tail >= 2 ? newId() : null;
        return replaceStep(d, step.id, (s) => ({
          ...s,
          actions: s.actions.map((a, i) =>
            i === index
              ? { ...a, parallelGroup: null }
              : i > index && i <= index + tail
                ? { ...a, parallelGroup: renamed }
                : a,
          ),
        }));
      }
      const above = step.actions[index - 1];
      if (!above) throw new DesignerError("The first action of a step has nothing above it to run together with.");
      const choice = [action, above].find((a) => WAITS_FOR_CHOICE.has(a.type));
      if (choice)
        throw new DesignerError(
          `${choice.name || "A question or branch"} waits for the wizard's choice, so it starts on its own, never together with another action.`,
        );
      const group = above.parallelGroup ?? newId();
      return replaceStep(d, step.id, (s) => ({
        ...s,
        actions: s.actions.map((a, i) =>
          i === index - 1 || i === index || (a.parallelGroup && a.parallelGroup === action.parallelGroup)
            ? { ...a, parallelGroup: group }
            : a,
        ),
      }));
    },
  }),

  setBranchTarget: (branchId: string, optionId: string, stepId: string | null): Command => ({
    label: "set branch target",
    apply: (d) => {
      if (stepId) locateStep(d, stepId);
      return replaceAction(d, branchId, (a) => {
        const targets = { ...((a.parameters.targets as Record<string, string> | undefined) ?? {}) };
        if (stepId) targets[optionId] = stepId;
        else delete targets[optionId];
        return { ...a, parameters: { ...a.parameters, targets } };
      });
    },
  }),

  /** "Create a new step for this answer", from the branch block itself: a new step at the end, targeted. */
  addStepForAnswer: (branchId: string, optionId: string, name: string, id?: string): Command => ({
    label: "add step for answer",
    apply: (d, newId) => {
      const stepId = id ?? newId();
      const withStep = commands.addStep(name, undefined, stepId).apply(d, newId);
      return commands.setBranchTarget(branchId, optionId, stepId).apply(withStep, newId);
    },
  }),
};
