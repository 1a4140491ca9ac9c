// The designer as a headless model: named commands over a draft, with undo
// and redo. The page only renders a draft and sends commands, so every edit a
// researcher can make is tested here without a browser.
import type { ActionVariant, StepVariant, TimeLimit } from "../protocol/document";
import type { After, DesignAction, DesignDraft, DesignStep } from "./types";
import { WAITS_FOR_CHOICE } from "./blocks";
import {
  clampIndex,
  DesignerError,
  leaveGroup,
  locateAction,
  locateStep,
  move,
  replaceAction,
  replaceStep,
  replaceStepVariant,
} from "./draft";
import type { Command } from "./history";

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
