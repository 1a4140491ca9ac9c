// What changed between two published versions of an experiment, as lines a
// researcher can read in the version history. Steps and actions are matched
// by id, which publishing keeps stable; everything is named, never shown by id.
import { canonicalJson } from "../protocol/canonical";
import { describeExit } from "../protocol/flow";
import type { ProtocolSnapshot } from "../protocol/snapshot";

export interface DiffLine {
  kind: "added" | "removed" | "changed" | "moved";
  what: "experiment" | "step" | "action";
  text: string;
}

type Step = ProtocolSnapshot["steps"][number];
type Action = Step["actions"][number];

const MAX_SHOWN = 80;

export function diffProtocols(before: ProtocolSnapshot, after: ProtocolSnapshot): DiffLine[] {
  const lines: DiffLine[] = [];
  const line = (kind: DiffLine["kind"], what: DiffLine["what"], text: string) => lines.push({ kind, what, text });
  const [was, now] = [before.experiment, after.experiment];
  if (was.name !== now.name)
    line("changed", "experiment", `Experiment renamed from ${show(was.name)} to ${show(now.name)}`);
  if (was.description !== now.description)
    line(
      "changed",
      "experiment",
      `Experiment description changed from ${show(was.description)} to ${show(now.description)}`,
    );
  if (was.robotId !== now.robotId)
    line("changed", "experiment", `Robot changed from ${show(was.robotId)} to ${show(now.robotId)}`);

  const oldSteps = new Map(before.steps.map((step, index) => [step.id, { step, index }]));
  const newSteps = new Map(after.steps.map((step, index) => [step.id, { step, index }]));
  const oldActions = actionsById(before);
  const newActions = actionsById(after);
  // A step is called by its current name wherever it still exists.
  const stepName = (id: string) => show((newSteps.get(id) ?? oldSteps.get(id))?.step.name ?? id);
  const removedActions = (step: Step) => {
    for (const action of step.actions) {
      if (!newActions.has(action.id))
        line("removed", "action", `Action ${show(nameOf(action))} removed from ${stepName(step.id)}`);
    }
  };

  for (const step of before.steps) {
    if (newSteps.has(step.id)) continue;
    line("removed", "step", `Step ${show(step.name)} removed`);
    removedActions(step);
  }
  const movedSteps = displaced(
    before.steps.filter((s) => newSteps.has(s.id)).map((s) => s.id),
    after.steps.filter((s) => oldSteps.has(s.id)).map((s) => s.id),
  );
  after.steps.forEach((step, index) => {
    const old = oldSteps.get(step.id);
    const where = stepName(step.id);
    if (!old) line("added", "step", `Step ${where} added at position ${index + 1}`);
    else {
      if (old.step.name !== step.name) line("changed", "step", `Step ${show(old.step.name)} renamed to ${where}`);
      if (movedSteps.has(step.id))
        line("moved", "step", `Step ${where} moved from position ${old.index + 1} to ${index + 1}`);
      if (old.step.description !== step.description)
        line(
          "changed",
          "step",
          `Step ${where}: description changed from ${show(old.step.description)} to ${show(step.description)}`,
        );
      // "Next" stays "next" when steps move around it: only a changed choice is a change.
      const [chose, chooses] = [old.step.after ?? NEXT, step.after ?? NEXT];
      if (canonicalJson(chose) !== canonicalJson(chooses)) {
        const [led, leads] = [describeExit(before.steps, old.index), describeExit(after.steps, index)];
        line("changed", "step", `Step ${where} now leads to ${leads} (it led to ${led})`);
      }
      removedActions(old.step);
    }
    const stayed = (s: Step) =>
      s.actions
        .filter((a) => oldActions.get(a.id)?.stepId === step.id && newActions.get(a.id)?.stepId === step.id)
        .map((a) => a.id);
    const movedActions = displaced(old ? stayed(old.step) : [], stayed(step));
    step.actions.forEach((action, position) => {
      const prior = oldActions.get(action.id);
      const name = show(nameOf(action));
      if (!prior) {
        line("added", "action", `Action ${name} added to ${where} at position ${position + 1}`);
        return;
      }
      if (prior.stepId !== step.id)
        line("moved", "action", `Action ${name} moved from ${stepName(prior.stepId)} to ${where}`);
      if (movedActions.has(action.id))
        line("moved", "action", `Action ${name} in ${where} moved from position ${prior.index + 1} to ${position + 1}`);
      if (nameOf(prior.action) !== nameOf(action))
        line("changed", "action", `Action ${show(nameOf(prior.action))} in ${where} renamed to ${name}`);
      if (prior.action.type !== action.type)
        line(
          "changed",
          "action",
          `Action ${name} in ${where}: type changed from ${show(prior.action.type)} to ${show(action.type)}`,
        );
      const labels = answerLabels([
        oldSteps.get(prior.stepId)?.step.actions[prior.index - 1],
        step.actions[position - 1],
      ]);
      if ((prior.action.note ?? "") !== (action.note ?? ""))
        line(
          "changed",
          "action",
          `Action ${name} in ${where}: note for the wizard ${noteChange(prior.action, action)}`,
        );
      for (const change of parameterChanges(prior.action, action, labels, stepName))
        line("changed", "action", `Action ${name} in ${where}: ${change}`);
    });
    const [wasTogether, isTogether] = [together(old?.step), together(step)];
    if (wasTogether.key !== isTogether.key) {
      line(
        "changed",
        "action",
        `Actions that run together in ${where} changed from ${wasTogether.text} to ${isTogether.text}`,
      );
    }
  });
  return lines;
}

const NEXT = { to: "next" } as const;

function noteChange(was: Action, now: Action): string {
  if (!was.note) return `added: ${show(now.note!)}`;
  if (!now.note) return "removed";
  return `changed from ${show(was.note)} to ${show(now.note)}`;
}

function actionsById(snapshot: ProtocolSnapshot) {
  return new Map(
    snapshot.steps.flatMap((step) =>
      step.actions.map((action, index) => [action.id, { action, index, stepId: step.id }] as const),
    ),
  );
}

/** One phrase per parameter that changed; a branch's targets one per answer. */
function parameterChanges(
  was: Action,
  now: Action,
  labels: Map<string, string>,
  stepName: (id: string) => string,
): string[] {
  const keys = [...new Set([...Object.keys(was.parameters), ...Object.keys(now.parameters)])].sort();
  return keys.flatMap((key) => {
    const [from, to] = [own(was.parameters, key), own(now.parameters, key)];
    if (same(from, to)) return [];
    if (key === "targets" && was.type === "branch" && now.type === "branch")
      return routeChanges(from, to, labels, stepName);
    if (from === undefined) return [`${key} set to ${show(to)}`];
    if (to === undefined) return [`${key} removed (was ${show(from)})`];
    return [`${key} changed from ${show(from)} to ${show(to)}`];
  });
}

/** One line per answer whose branch target changed, the answer named by its label. */
function routeChanges(
  from: unknown,
  to: unknown,
  labels: Map<string, string>,
  stepName: (id: string) => string,
): string[] {
  const [was, now] = [targetsOf(from), targetsOf(to)];
  return [...new Set([...Object.keys(was), ...Object.keys(now)])].sort().flatMap((option) => {
    const [a, b] = [own(was, option), own(now, option)];
    if (a === b) return [];
    const answer = `answer ${show(labels.get(option) ?? option)}`;
    const target = (id: unknown) => (typeof id === "string" ? stepName(id) : show(id));
    if (a === undefined) return [`${answer} now goes to ${target(b)}`];
    if (b === undefined) return [`${answer} no longer goes to ${target(a)}`];
    return [`${answer} goes to ${target(b)} instead of ${target(a)}`];
  });
}

function targetsOf(value: unknown): Record<string, unknown> {
  return value && typeof value === "object" && !Array.isArray(value) ? (value as Record<string, unknown>) : {};
}

/** Option ids to labels, from the questions before a branch (the later one wins). */
function answerLabels(questions: Array<Action | undefined>): Map<string, string> {
  const labels = new Map<string, string>();
  for (const question of questions) {
    const options = question?.type === "record_answer" ? question.parameters.options : undefined;
    for (const option of Array.isArray(options) ? options : []) {
      const { id, label } = targetsOf(option);
      if (typeof id === "string" && typeof label === "string") labels.set(id, label);
    }
  }
  return labels;
}

/** A step's run-together groups: neighbours sharing a group start together. */
function together(step: Step | undefined): { key: string; text: string } {
  const runs: Action[][] = [];
  step?.actions.forEach((action, i) => {
    const previous = step.actions[i - 1];
    if (action.parallelGroup && previous?.parallelGroup === action.parallelGroup) runs.at(-1)!.push(action);
    else runs.push([action]);
  });
  const groups = runs.filter((run) => run.length > 1);
  return {
    key: groups.map((run) => run.map((a) => a.id).join(",")).join(";"),
    text: groups.length ? groups.map((run) => run.map((a) => show(nameOf(a))).join(" + ")).join(", ") : "none",
  };
}

/**
 * The ids whose order relative to the others changed: all but a longest run
 * that kept its order. Shifting everything down by one moves nothing.
 */
function displaced(before: string[], after: string[]): Set<string> {
  const rank = new Map(before.map((id, i) => [id, i]));
  const order = after.map((id) => rank.get(id)!);
  const length = order.map(() => 1);
  const previous = order.map(() => -1);
  // Quadratic, but a step holds at most 500 actions and an experiment 500 steps.
  for (let i = 0; i < order.length; i++) {
    for (let j = 0; j < i; j++) {
      if (order[j]! >= order[i]! || length[j]! + 1 <= length[i]!) continue;
      length[i] = length[j]! + 1;
      previous[i] = j;
    }
  }
  const kept = new Set<string>();
  for (let i = length.indexOf(Math.max(...length)); i >= 0; i = previous[i]!) kept.add(after[i]!);
  return new Set(after.filter((id) => !kept.has(id)));
}

function nameOf(action: Action): string {
  return action.name || action.type;
}

function own(record: Record<string, unknown>, key: string): unknown {
  return Object.hasOwn(record, key) ? record[key] : undefined;
}

/** Deep equality that ignores key order, as stored JSON does. */
export function same(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (!a || !b || typeof a !== "object" || typeof b !== "object" || Array.isArray(a) !== Array.isArray(b)) return false;
  const [x, y] = [a as Record<string, unknown>, b as Record<string, unknown>];
  const keys = Object.keys(x);
  return keys.length === Object.keys(y).length && keys.every((k) => Object.hasOwn(y, k) && same(x[k], y[k]));
}

function show(value: unknown): string {
  const text = JSON.stringify(value) ?? "nothing";
  const chars = Array.from(text);
  return chars.length > MAX_SHOWN ? `${chars.slice(0, MAX_SHOWN - 1).join("")}…` : text;
}
