// The fidelity report of one trial: what was planned (the protocol version)
// against what happened (its events). Pure, so the analysis page, exports and
// study tables all compute the same figures.
import { actionName, type ActionNames } from "@/core/designer/action-name";
import type { TrialEvent, TrialProtocol } from "@/core/trial";
import { OUTCOME_WORDS, type UndoneOutcome } from "@/core/trial/outcomes";
import { CONTROL_TYPES } from "@/core/trial/types";
import { answerOf, recordedAnswers, type RecordedAnswer } from "./answers";
import { loopCounts, type LoopCount } from "./loop-counts";
import { type Move, stepVisits } from "./moves";

/** `not_sent`, `unknown` and `failed` are the three words of src/core/trial/outcomes.ts. */
export type ActionOutcome =
  | "executed"
  | "skipped"
  | "failed"
  | "not_sent"
  | "unknown"
  | "timed_out"
  | "not_reached"
  | "running";

/** An outcome in the researcher's words: the three of a robot action not done as the trial log says them. */
export function outcomeWords(outcome: ActionOutcome): string {
  return outcome in OUTCOME_WORDS ? OUTCOME_WORDS[outcome as UndoneOutcome] : outcome.replace("_", " ");
}

export interface PlannedAction {
  stepId: string;
  actionId: string;
  type: string;
  name: string;
  outcome: ActionOutcome;
  outOfOrder: boolean;
  requestedMs: number | null;
  /** requested → completed (or failed / timed out). */
  durationMs: number | null;
  /** requested → dispatched: how long the platform took to reach the robot. */
  dispatchLatencyMs: number | null;
  /**
   * Whether the robot itself said the action was done ("robot"), or its
   * completion was only an estimate or a delivery ("unconfirmed"); null when
   * the log does not say (not completed, not a robot action, or an older log).
   */
  confirmation: "robot" | "unconfirmed" | null;
  /** The answer recorded, by its label, for a question that was answered; otherwise null. */
  answer: string | null;
}

export interface StepTiming {
  stepId: string;
  name: string;
  reached: boolean;
  /** How many times the trial entered it: more than once round a loop (or by a jump back). */
  entered: number;
  /** Its first entry, and when the trial left that visit. */
  enteredMs: number | null;
  leftMs: number | null;
  durationMs: number | null;
}

export interface FidelityReport {
  actions: PlannedAction[];
  steps: StepTiming[];
  unscripted: Array<{
    actionId: string;
    type: string;
    name: string;
    requestedMs: number | null;
    /** From its request to its end, as a scripted action's; null while it has not ended. */
    durationMs: number | null;
    parameters: Record<string, unknown>;
  }>;
  branches: { byLogic: number; byHand: number };
  /** Each loop of the protocol: how many times it went back, and whether its bound was reached. */
  loops: LoopCount[];
  /** How many times each kind of move took the trial into a step: the robot's senses, a timer, the wizard's next, go on, answer or jump. */
  moves: Record<Move["by"], number>;
  /** Every answer recorded, in log order. */
  answers: RecordedAnswer[];
  deviations: Record<string, number>;
  totals: {
    planned: number;
    executed: number;
    skipped: number;
    failed: number;
    notSent: number;
    unknown: number;
    timedOut: number;
    notReached: number;
    outOfOrder: number;
    unscripted: number;
  };
  /**
   * Execution fidelity, in %: scripted actions of the steps the trial reached
   * that were executed as designed (in order, not skipped, not failed), over
   * those actions. Steps a branch did not take do not count against it.
   */
  executionFidelity: number;
  completed: boolean;
}

type E = TrialEvent & {
  actionId?: string;
  stepId?: string | null;
  actionType?: string;
  scripted?: boolean;
  parameters?: Record<string, unknown>;
};

/** `names`: the robot plugin's names of its own actions, so unlabelled actions read as the library shows them. */
export function fidelityReport(protocol: TrialProtocol, events: TrialEvent[], names?: ActionNames): FidelityReport {
  const log = events as E[];
  // Each action's events, in log order: looked up per planned action, not searched for in the whole log
  // (a log of 100k events searched a dozen times per action took longer than everything else on the page).
  const byAction = new Map<string, E[]>();
  for (const e of log) {
    if (e.actionId === undefined) continue;
    const events = byAction.get(e.actionId);
    if (events) events.push(e);
    else byAction.set(e.actionId, [e]);
  }
  const ofAction = (actionId: string) => byAction.get(actionId) ?? [];
  const first = (type: string, actionId: string) => ofAction(actionId).find((e) => e.type === type);
  const entries = log.filter((e) => e.type === "step.entered");
  const end =
    log.find((e) => e.type === "trial.completed" || e.type === "trial.aborted")?.relMs ?? log.at(-1)?.relMs ?? null;

  const steps: StepTiming[] = protocol.steps.map((step) => {
    const entered = entries.find((e) => e.stepId === step.id);
    const next = entered ? entries.find((e) => e.seq > entered.seq) : undefined;
    const leftMs = entered ? (next?.relMs ?? end) : null;
    const enteredMs = entered?.relMs ?? null;
    return {
      stepId: step.id,
      name: step.name,
      reached: !!entered,
      entered: entries.filter((e) => e.stepId === step.id).length,
      enteredMs,
      leftMs,
      durationMs: enteredMs !== null && leftMs !== null ? leftMs - enteredMs : null,
    };
  });

  /** When an action ended, however it ended: its duration runs from its request to here. */
  const finishedOf = (actionId: string) =>
    first("action.completed", actionId) ??
    first("action.failed", actionId) ??
    first("action.not_sent", actionId) ??
    first("action.unknown", actionId) ??
    first("action.timed_out", actionId) ??
    first("answer.recorded", actionId) ??
    first("branch.resolved", actionId) ??
    first("wait.resolved", actionId);

  const actions: PlannedAction[] = protocol.steps.flatMap((step) =>
    step.actions.map((a) => {
      const requested =
        first("action.requested", a.id) ??
        first("answer.recorded", a.id) ??
        first("branch.resolved", a.id) ??
        first("wait.resolved", a.id);
      const finished = finishedOf(a.id);
      const dispatched = first("action.dispatched", a.id);
      const outcome: ActionOutcome = first("action.skipped", a.id)
        ? "skipped"
        : first("action.failed", a.id)
          ? "failed"
          : first("action.not_sent", a.id)
            ? "not_sent"
            : // A later word of the robot's on it (its completion) makes it done.
              first("action.unknown", a.id) && !first("action.completed", a.id)
              ? "unknown"
              : first("action.timed_out", a.id)
                ? "timed_out"
                : finished
                  ? "executed"
                  : requested
                    ? "running"
                    : "not_reached";
      const at = (e?: E) => e?.relMs ?? null;
      return {
        stepId: step.id,
        actionId: a.id,
        type: a.type,
        name: actionName(a, names),
        outcome,
        outOfOrder: ofAction(a.id).some((e) => e.deviation === "out_of_order"),
        requestedMs: at(requested),
        durationMs:
          requested && finished && at(finished) !== null && at(requested) !== null
            ? at(finished)! - at(requested)!
            : null,
        dispatchLatencyMs:
          requested && dispatched && !(CONTROL_TYPES as readonly string[]).includes(a.type)
            ? at(dispatched)! - at(requested)!
            : null,
        confirmation: confirmationOf(first("action.completed", a.id)),
        answer: answerOf(first("answer.recorded", a.id) ?? {}) ?? null,
      };
    }),
  );

  const unscripted = log
    .filter((e) => e.type === "action.requested" && e.scripted === false)
    .map((e) => {
      const end = finishedOf(e.actionId!)?.relMs ?? null;
      return {
        actionId: e.actionId!,
        type: e.actionType!,
        name: actionName({ type: e.actionType!, parameters: e.parameters }, names),
        requestedMs: e.relMs,
        durationMs: end !== null && e.relMs !== null ? end - e.relMs : null,
        parameters: e.parameters ?? {},
      };
    });
  const deviations: Record<string, number> = {};
  for (const e of log) if (e.deviation) deviations[e.deviation] = (deviations[e.deviation] ?? 0) + 1;
  const count = (o: ActionOutcome) => actions.filter((a) => a.outcome === o).length;
  const reached = new Set(steps.filter((s) => s.reached).map((s) => s.stepId));
  const inReached = actions.filter((a) => reached.has(a.stepId));
  const faithful = inReached.filter((a) => a.outcome === "executed" && !a.outOfOrder).length;
  return {
    actions,
    steps,
    unscripted,
    branches: {
      byLogic: log.filter((e) => e.type === "branch.resolved").length,
      byHand: log.filter((e) => e.type === "step.entered" && e.deviation === "manual_jump").length,
    },
    loops: loopCounts(protocol, events),
    moves: countMoves(events),
    answers: recordedAnswers(protocol, events, names),
    deviations,
    totals: {
      planned: actions.length,
      executed: count("executed"),
      skipped: count("skipped"),
      failed: count("failed"),
      notSent: count("not_sent"),
      unknown: count("unknown"),
      timedOut: count("timed_out"),
      notReached: count("not_reached"),
      outOfOrder: actions.filter((a) => a.outOfOrder).length,
      unscripted: unscripted.length,
    },
    executionFidelity: inReached.length ? Math.round((faithful / inReached.length) * 1000) / 10 : 0,
    completed: log.some((e) => e.type === "trial.completed"),
  };
}

function countMoves(events: readonly TrialEvent[]): FidelityReport["moves"] {
  const moves: FidelityReport["moves"] = {
    start: 0,
    next: 0,
    answer: 0,
    jump: 0,
    timer: 0,
    loop: 0,
    bound: 0,
    senses: 0,
    go_on: 0,
  };
  for (const visit of stepVisits(events)) moves[visit.move.by]++;
  return moves;
}

/** What confirmed a completion, as the robot link wrote it into the event's detail. */
function confirmationOf(completed?: E): PlannedAction["confirmation"] {
  const detail = completed && "detail" in completed ? completed.detail : undefined;
  const confirmation = detail?.confirmation as { confirmed?: unknown } | undefined;
  if (!confirmation || typeof confirmation !== "object") return null;
  return confirmation.confirmed === true ? "robot" : "unconfirmed";
}
