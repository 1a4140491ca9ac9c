// Checking a draft before it is piloted or published: every problem a
// researcher can fix in the designer, placed on its step and action and said
// without the engine's vocabulary. The flow checks walk the draft the way the
// trial engine does (../trial/decide.ts).
import {
  type ActionPortability,
  parseActionType,
  portability,
  validateParameters,
  type Channels,
  type Plugin,
} from "../plugins";
import { finish, type Work } from "../work";
import { awaitedEvents, exitBy, exitOf, TIMED_BLOCKS, timeLimitsOf, waysBy } from "../protocol/flow";
import { blockFor, type Block } from "./blocks";
import { loopIssues } from "./loop-issues";
import { stepLabel, upper } from "./step-label";
import type { DesignAction, DesignDraft, DesignStep } from "./types";

export interface DesignIssue {
  severity: "error" | "warning";
  code: string;
  message: string;
  stepId?: string;
  actionId?: string;
  parameter?: string;
}

export function hasErrors(issues: DesignIssue[]): boolean {
  return issues.some((i) => i.severity === "error");
}

interface Placed {
  issue: DesignIssue;
  step: number;
  /** -1 for the step itself, so its own issues come before its actions'. */
  action: number;
}

interface Option {
  id: string;
  label: string;
}

/** Where each answer of a branch leads: a step index, or why it leads nowhere. */
type Route = { option: Option; to: number } | { option: Option; to: null; why: "unset" | "gone" };

/** With `channels` (this server's ways to the robot), an action none of them carries is said not to run here. */
export function validateDesign(draft: DesignDraft, plugin: Plugin | null, channels?: Channels): DesignIssue[] {
  return finish(validating(draft, plugin, channels));
}

/** validateDesign as work that yields after each action, for the server to run in slices. */
export function* validating(draft: DesignDraft, plugin: Plugin | null, channels?: Channels): Work<DesignIssue[]> {
  if (draft.steps.length === 0) {
    return [
      {
        severity: "error",
        code: "no_steps",
        message: "The experiment has no steps yet. Add a step to say what happens first.",
      },
    ];
  }
  const placed: Placed[] = [];
  const indexById = new Map(draft.steps.map((s, i) => [s.id, i]));
  const reported = new Set<string>();
  for (const [s, step] of draft.steps.entries()) {
    const add = (action: number, issue: Omit<DesignIssue, "stepId">) =>
      placed.push({ step: s, action, issue: { ...issue, stepId: step.id } });
    const where = stepLabel(step, s);
    if (step.actions.length === 0) {
      add(-1, {
        severity: "error",
        code: "empty_step",
        message: `${upper(where)} has no actions yet. Add what the robot or the wizard should do, or remove the step.`,
      });
    }
    const end = step.actions.findIndex((a) => a.type === "end_trial");
    for (const [a, action] of step.actions.entries()) {
      yield;
      const block = blockFor(action.type, plugin);
      const name = actionLabel(action, block);
      const at = (issue: Omit<DesignIssue, "stepId" | "actionId">) => add(a, { ...issue, actionId: action.id });
      if (!block) at({ severity: "error", code: "unknown_block", message: unknownMessage(action, name, plugin) });
      for (const problem of block ? validateParameters(block.parameterSchema, action.parameters) : []) {
        reported.add(`${action.id}\n${problem.parameter}\n${problem.message}`);
        at({
          severity: "error",
          code: "parameter",
          parameter: problem.parameter,
          message: `${name}: ${titled(problem.message, problem.parameter, block)}.`,
        });
      }
      if (end >= 0 && a > end) {
        at({
          severity: "warning",
          code: "after_end",
          message: `${name} comes after "End trial" in ${where}, so it never runs.`,
        });
      }
      if (
        action.parallelGroup &&
        ![step.actions[a - 1], step.actions[a + 1]].some((n) => n?.parallelGroup === action.parallelGroup)
      ) {
        at({
          severity: "warning",
          code: "run_together_alone",
          message: `${name} is set to run together with other actions, but no action next to it is in its group, so it runs on its own.`,
        });
      }
      // The engine runs a time limit of a question or a wait only: on any other action it would silently do nothing.
      if (action.timeLimit && !TIMED_BLOCKS.has(action.type)) {
        at({
          severity: "error",
          code: "time_limit_not_question",
          message: `${name} has a time limit, but only a "Record answer" or a "Wait for" can have one (a step can too, in its properties).`,
        });
      }
      if (action.type === "wait_for") for (const issue of waitIssues(action, name, indexById)) at(issue);
      if (action.type === "record_answer") {
        const seen = new Set<string>();
        for (const option of optionsOf(action)) {
          const label = option.label.trim().toLowerCase();
          if (seen.has(label)) {
            at({
              severity: "warning",
              code: "duplicate_option",
              parameter: "options",
              message: `${name} offers the answer "${option.label}" twice; the wizard cannot tell them apart.`,
            });
          }
          seen.add(label);
        }
      }
      if (action.type !== "branch") continue;
      const routes = routesOf(step, a, indexById);
      if (!routes) {
        at({
          severity: "error",
          code: "branch_without_answer",
          message: `${name} must come right after a "Record answer" block in the same step: it chooses the next step from that answer.`,
        });
      }
      for (const route of routes ?? []) {
        if (route.to !== null) continue;
        const message =
          route.why === "unset"
            ? `${name}: choose the step the answer "${route.option.label}" leads to.`
            : `${name}: the answer "${route.option.label}" leads to a step that is no longer in the experiment. Choose another step.`;
        at({ severity: "error", code: "branch_target_missing", parameter: "targets", message });
      }
    }
  }
  placed.push(...flowIssues(draft, indexById));
  if (plugin) placed.push(...(yield* robotIssues(draft, plugin, reported, channels)));
  return placed.sort((x, y) => x.step - y.step || x.action - y.action).map((p) => p.issue);
}

/** The answers of a branch's question with their targets, or null when no question comes right before it. */
function routesOf(step: DesignStep, branchIndex: number, indexById: Map<string, number>): Route[] | null {
  const question = step.actions[branchIndex - 1];
  if (question?.type !== "record_answer") return null;
  const targets = step.actions[branchIndex]!.parameters.targets;
  const table = targets && typeof targets === "object" ? (targets as Record<string, unknown>) : {};
  return optionsOf(question).map((option): Route => {
    const target = Object.hasOwn(table, option.id) ? table[option.id] : undefined;
    if (typeof target !== "string" || target === "") return { option, to: null, why: "unset" };
    const to = indexById.get(target);
    return to === undefined ? { option, to: null, why: "gone" } : { option, to };
  });
}

function optionsOf(action: DesignAction): Option[] {
  const options = action.parameters.options;
  if (!Array.isArray(options)) return [];
  return options.flatMap((o: unknown) => {
    const { id, label } = (o && typeof o === "object" ? o : {}) as Record<string, unknown>;
    return typeof id === "string" ? [{ id, label: typeof label === "string" ? label : id }] : [];
  });
}

/** A wait that waits for nothing, or an event of it that leads nowhere. */
function waitIssues(
  action: DesignAction,
  name: string,
  indexById: Map<string, number>,
): Array<Omit<DesignIssue, "stepId" | "actionId">> {
  const events = awaitedEvents(action);
  if (events.length === 0 && !action.timeLimit)
    return [
      {
        severity: "error",
        code: "wait_for_nothing",
        parameter: "events",
        message: `${name} waits for nothing: choose at least one event the robot senses, or a time limit.`,
      },
    ];
  return events.flatMap((e) => {
    if (e.after.to !== "step") return [];
    const gone = e.after.stepId ? !indexById.has(e.after.stepId) : false;
    if (e.after.stepId && !gone) return [];
    const message = gone
      ? `${name}: the event "${e.event}" leads to a step that is no longer in the experiment. Choose another step.`
      : `${name}: choose the step the event "${e.event}" leads to.`;
    return [{ severity: "error" as const, code: "wait_target_missing", parameter: "events", message }];
  });
}

/** The steps a wait's events lead to (a step or the end is a way on; one that is gone is told by waitIssues). */
function waitExits(draft: DesignDraft, s: number): { exits: number[]; ends: boolean } {
  const ways = draft.steps[s]!.actions.flatMap((a) => awaitedEvents(a).map((e) => exitBy(draft.steps, s, e.after)));
  return {
    exits: ways.flatMap((exit) => (exit.to === "step" ? [exit.index] : [])),
    ends: ways.some((exit) => exit.to === "end"),
  };
}

/** The steps a step's time limits (its own, its questions') lead to; one to a step that is gone is told. */
function timeLimitExits(draft: DesignDraft, s: number, tell: (message: string) => void): number[] {
  const step = draft.steps[s]!;
  return timeLimitsOf(step).flatMap((limit) => {
    const exits = waysBy(draft.steps, s, limit.after).map((way) => way.exit);
    if (exits.some((exit) => exit.to === "missing"))
      tell(
        `${upper(stepLabel(step, s))} has a time limit that leads to a step that is no longer in the experiment. Choose where it leads in the properties.`,
      );
    return exits.flatMap((exit) => (exit.to === "step" ? [exit.index] : []));
  });
}

// A branch already reported as broken is read as going to the targets it has
// and also falling through, so one mistake does not surface again as
// unreachable steps or an endless trial.
function flowIssues(draft: DesignDraft, indexById: Map<string, number>): Placed[] {
  const issues: Placed[] = [];
  const flow = draft.steps.map((step, s) => {
    // A time limit is a way on of its own, taken whatever else the step does.
    const exits: number[] = timeLimitExits(draft, s, (message) =>
      issues.push({
        step: s,
        action: -1,
        issue: { severity: "error", code: "after_target_missing", message, stepId: step.id },
      }),
    );
    // A wait's events are ways on too; the wizard's go on still takes the step's own way, so it never replaces it.
    const waits = waitExits(draft, s);
    exits.push(...waits.exits);
    for (const [a, action] of step.actions.entries()) {
      if (action.type === "end_trial") return { exits, ends: true };
      const routes = action.type === "branch" ? routesOf(step, a, indexById) : null;
      for (const route of routes ?? []) if (route.to !== null) exits.push(route.to);
      if (routes?.length && routes.every((r) => r.to !== null)) return { exits, ends: waits.ends };
    }
    // A loop leads two ways: back, and on after its last time.
    const ways = waysBy(draft.steps, s, step.after ?? { to: "next" }).map((way) => way.exit);
    if (ways.some((exit) => exit.to === "missing")) {
      const message = `${upper(stepLabel(step, s))} leads to a step that is no longer in the experiment. Choose where it leads in the step's properties.`;
      issues.push({
        step: s,
        action: -1,
        issue: { severity: "error", code: "after_target_missing", message, stepId: step.id },
      });
    }
    const onward = ways.flatMap((exit) => (exit.to === "step" ? [exit.index] : []));
    return { exits: [...exits, ...onward], ends: waits.ends || ways.some((exit) => exit.to !== "step") };
  });
  issues.push(...fallThroughIssues(draft, indexById));
  const loops = loopIssues(
    draft.steps,
    flow.map((f) => f.exits),
  );
  issues.push(...loops.map(({ step, issue }) => ({ step, action: -1, issue })));
  const reached = new Set([0]);
  for (const s of reached) for (const next of flow[s]!.exits) reached.add(next);
  const canEnd = flow.map((f) => f.ends);
  for (let changed = true; changed; ) {
    changed = false;
    flow.forEach((f, s) => {
      if (canEnd[s] || !f.exits.some((e) => canEnd[e])) return;
      canEnd[s] = true;
      changed = true;
    });
  }
  draft.steps.forEach((step, s) => {
    if (reached.has(s)) return;
    const message = `${upper(stepLabel(step, s))} can never be reached: the steps before it end the trial or branch elsewhere, and no branch leads to it.`;
    issues.push({
      step: s,
      action: -1,
      issue: { severity: "error", code: "unreachable_step", message, stepId: step.id },
    });
  });
  const stuck = draft.steps.findIndex((_, s) => reached.has(s) && !canEnd[s]);
  // A loop with no way out is already told, with its steps named.
  if (stuck >= 0 && !loops.some((l) => l.issue.code === "loop_no_way_out")) {
    const step = draft.steps[stuck]!;
    const message = `The trial can never end from ${stepLabel(step, stuck)}: every way on loops back without reaching an "End trial" block or a step that leads to the end.`;
    issues.push({ step: stuck, action: -1, issue: { severity: "error", code: "no_end", message, stepId: step.id } });
  }
  return issues;
}

/**
 * An answer's step that runs on into the step of another answer of the same
 * question: the participant who gave one answer hears the response to the
 * other too. Each answer's path is followed through steps without a branch
 * (where each leads after its actions), as the engine would.
 */
function fallThroughIssues(draft: DesignDraft, indexById: Map<string, number>): Placed[] {
  const issues: Placed[] = [];
  const reported = new Set<number>();
  draft.steps.forEach((step, s) => {
    step.actions.forEach((action, a) => {
      if (action.type !== "branch") return;
      const routes = (routesOf(step, a, indexById) ?? []).filter((r) => r.to !== null && r.to !== s);
      const answerOf = new Map(routes.map((r) => [r.to!, r.option.label]));
      for (const route of routes) {
        const from = route.to!;
        if (reported.has(from)) continue;
        const into = runsInto(draft, from, answerOf);
        if (into === null) continue;
        reported.add(from);
        const fromStep = draft.steps[from]!;
        const message = `After ${stepLabel(fromStep, from)} (the answer "${route.option.label}"), the trial goes on to ${stepLabel(draft.steps[into]!, into)}, the step for the answer "${answerOf.get(into)}", so both responses are given. Set where ${stepLabel(fromStep, from)} leads, for example to the step where the answers meet.`;
        issues.push({
          step: from,
          action: -1,
          issue: { severity: "warning", code: "answer_falls_through", message, stepId: fromStep.id },
        });
      }
    });
  });
  return issues;
}

/** The first step of another answer that `from` runs into without a branch in between, if any. */
function runsInto(draft: DesignDraft, from: number, answers: Map<number, string>): number | null {
  const seen = new Set<number>();
  for (let at = from; !seen.has(at); ) {
    seen.add(at);
    const step = draft.steps[at]!;
    if (step.actions.some((a) => a.type === "branch" || a.type === "end_trial")) return null;
    const exit = exitOf(draft.steps, at);
    if (exit.to !== "step") return null;
    if (answers.has(exit.index) && answers.get(exit.index) !== answers.get(from)) return exit.index;
    at = exit.index;
  }
  return null;
}

function* robotIssues(draft: DesignDraft, plugin: Plugin, reported: Set<string>, channels?: Channels): Work<Placed[]> {
  // A step's variant's actions are placed after the step's own; an action's variant is placed on its action.
  const position = new Map(
    draft.steps.flatMap((step, s) => [
      ...step.actions.map((action, a) => [action.id, { step, s, action, a }] as const),
      ...Object.values(step.variants ?? {}).flatMap((variant) =>
        variant.actions.map((action) => [action.id, { step, s, action, a: step.actions.length }] as const),
      ),
    ]),
  );
  const placed: Placed[] = [];
  // A step at a time: the report of 50,000 actions at once would hold the server for most of a second.
  for (const step of draft.steps) {
    yield;
    placed.push(...portability({ steps: [step] }, plugin, channels).actions.flatMap(placedOf));
  }
  return placed;

  function placedOf(result: ActionPortability): Placed[] {
    const { step, s, action, a } = position.get(result.actionId)!;
    const block = blockFor(result.type, plugin);
    if (!block) return []; // already an unknown block
    const place = (issue: Omit<DesignIssue, "stepId" | "actionId">): Placed => ({
      step: s,
      action: a,
      issue: { ...issue, stepId: step.id, actionId: action.id },
    });
    const name = `${actionLabel(action, block)}${result.condition === undefined ? "" : ` in condition "${result.condition}"`}`;
    if (result.status === "unsupported") {
      return [
        place({
          severity: "warning",
          code: "unsupported_on_robot",
          message: `${name} cannot run on ${plugin.name}: ${result.reason}`,
        }),
      ];
    }
    return result.problems
      .filter((p) => !reported.has(`${action.id}\n${p.parameter}\n${p.message}`))
      .map((p) =>
        place({
          severity: "error",
          code: "parameter",
          parameter: p.parameter,
          message: `${name} on ${plugin.name}: ${titled(p.message, p.parameter, block)}.`,
        }),
      );
  }
}

function unknownMessage(action: DesignAction, name: string, plugin: Plugin | null): string {
  const parsed = parseActionType(action.type);
  if (parsed.kind !== "robot")
    return `${name} is a kind of action the designer does not know ("${action.type}"). Replace it with a block from the library.`;
  if (!plugin) return `${name} needs the plugin of the robot "${parsed.robotId}", which is not loaded.`;
  if (plugin.robotId !== parsed.robotId)
    return `${name} is an action of the robot "${parsed.robotId}", not of ${plugin.name}.`;
  return `${plugin.name} has no action "${parsed.actionId}", which ${name} needs. The plugin may have changed: replace it with a block from the library.`;
}

// Validation names a parameter by its key; the properties form shows its title.
function titled(message: string, parameter: string, block: Block | undefined): string {
  const title = block?.parameterSchema.properties[parameter]?.title;
  return typeof title === "string" ? message.replace(`"${parameter}"`, `"${title}"`) : message;
}

function actionLabel(action: DesignAction, block: Block | undefined): string {
  return `"${action.name.trim() || block?.name || action.type}"`;
}
