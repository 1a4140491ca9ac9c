// The trial engine: (state, command) → the events it causes, or a rejection
// the wizard can read. Pure: the runtime supplies ids, clock and robot.
import { actionName } from "../designer/action-name";
import { type EventNames, NO_EVENT_NAMES } from "../plugins/event-names";
import { applyInPlace, readThrough } from "./fold";
import { exitNow, follow, loopName } from "./loops";
import { answerOptions, branchTarget, findAction, findStep, nextUnit } from "./protocol";
import { FINISHED, timerFired, withTimers } from "./timers";
import { goOn, sensed, waitingWords } from "./waits";
import type { Command, Decision, DeviationKind, EngineEvent, ProtocolAction, TrialProtocol, TrialState } from "./types";

const ok = (...events: EngineEvent[]): Decision => ({ ok: true, events });
const no = (reason: string): Decision => ({ ok: false, reason });

/** What `command` causes in `state`, with the timers it starts and cancels; `names` name the robot's events in refusals. */
export function decide(
  protocol: TrialProtocol,
  state: TrialState,
  command: Command,
  names: EventNames = NO_EVENT_NAMES,
): Decision {
  const decision = decideCommand(protocol, state, command, names);
  return decision.ok ? ok(...withTimers(protocol, state, decision.events)) : decision;
}

function decideCommand(protocol: TrialProtocol, state: TrialState, command: Command, names: EventNames): Decision {
  switch (command.kind) {
    case "start": {
      if (state.status !== "scheduled") return no("This trial has already started.");
      const first = protocol.steps[0];
      if (!first) return no("The protocol has no steps.");
      return ok({ type: "trial.started" }, { type: "step.entered", stepId: first.id, via: "start" });
    }
    case "note":
      if (!command.text.trim()) return no("The note is empty.");
      return ok({ type: "note.added", text: command.text });
    case "recording":
      return ok({ type: "recording.started", recordingId: command.recordingId, offsetMs: command.offsetMs });
    case "robot_problem":
      // Logged whenever the link is open, before the start too (state subscriptions are refused as it connects).
      if (state.status === "completed" || state.status === "aborted") return no("This trial has already ended.");
      if (!command.text.trim()) return no("The robot's problem has no text.");
      return ok({ type: "robot.problem", text: command.text });
    case "sensed":
      return sensed(protocol, state, command);
    case "abort":
      if (state.status === "completed" || state.status === "aborted") return no("This trial has already ended.");
      return ok({ type: "trial.aborted", reason: command.reason });
    case "emergency_stop":
      if (state.status !== "in_progress" && state.status !== "paused") return no("The trial is not running.");
      return ok({ type: "trial.emergency_stop" });
    case "resume":
      if (state.status !== "paused") return no("The trial is not paused.");
      return ok({ type: "trial.resumed" });
    case "dispatched":
    case "completed":
    case "failed":
    case "not_sent":
    case "unknown":
    case "timed_out":
      return robotReport(state, command);
  }
  if (state.status === "paused") return no("The trial is paused: resume it first.");
  if (state.status !== "in_progress") return no("The trial is not running.");
  switch (command.kind) {
    case "pause":
      return ok({ type: "trial.paused" });
    case "complete":
      return ok({
        type: "trial.completed",
        ...(reachedEnd(protocol, state) ? {} : { deviation: "ended_early" as const }),
      });
    case "next":
      return next(protocol, state, names);
    case "trigger":
      return trigger(protocol, state, command.actionId, names);
    case "skip":
      return skip(protocol, state, command.actionId);
    case "answer":
      return answer(protocol, state, command.actionId, command.optionId);
    case "jump": {
      const target = findStep(protocol, command.stepId);
      if (!target) return no("That step is not in this protocol.");
      if (command.stepId === state.currentStepId) return no("The trial is already at that step.");
      return ok({ type: "step.entered", stepId: command.stepId, via: "manual_jump", deviation: "manual_jump" });
    }
    case "go_on":
      return goOn(protocol, state);
    case "timer_fired":
      return timerFired(protocol, state, command.timerId);
    case "unscripted":
      if (state.actions[command.actionId]) return no("That action id is already used.");
      return ok({
        type: "action.requested",
        stepId: state.currentStepId,
        actionId: command.actionId,
        actionType: command.actionType,
        parameters: command.parameters,
        scripted: false,
        deviation: "unscripted",
      });
  }
}

function next(protocol: TrialProtocol, state: TrialState, names: EventNames): Decision {
  // A designed pause holds the protocol: what follows waits until it is over.
  const holding = findStep(protocol, state.currentStepId)!.step.actions.find(
    (a) =>
      a.type === "pause" && (state.actions[a.id]?.status === "requested" || state.actions[a.id]?.status === "running"),
  );
  if (holding) return no(`Wait: the ${Number(holding.parameters.seconds ?? 0)} s pause is still running.`);
  const unit = nextUnit(protocol, state);
  if (unit.length > 0) return request(state, unit, undefined, names);
  const { step, index } = findStep(protocol, state.currentStepId)!;
  return ok(...follow(protocol, state, index, step.after ?? { to: "next" }, loopName(step.id), "next"));
}

function trigger(protocol: TrialProtocol, state: TrialState, actionId: string, names: EventNames): Decision {
  const found = findAction(protocol, actionId);
  if (!found) return no("That action is not in this protocol; use an unscripted action instead.");
  if (found.step.id !== state.currentStepId)
    return no(`"${actionName(found.action)}" belongs to another step: jump to "${found.step.name}" first.`);
  if (state.actions[actionId]?.status !== "waiting") return no(`"${actionName(found.action)}" has already run.`);
  const inTurn = nextUnit(protocol, state).some((a) => a.id === actionId);
  return request(state, [found.action], inTurn ? undefined : "out_of_order", names);
}

function request(
  state: TrialState,
  unit: ProtocolAction[],
  deviation: DeviationKind | undefined,
  names: EventNames,
): Decision {
  const stepId = state.currentStepId!;
  const events: EngineEvent[] = [];
  for (const action of unit) {
    if (action.type === "record_answer") {
      const labels = answerOptions(action)
        .map((o) => o.label)
        .join(" or ");
      return no(`Record the participant's answer: ${labels}.`);
    }
    if (action.type === "branch") return no("This branch follows the recorded answer: record the answer first.");
    if (action.type === "wait_for") return no(waitingWords(action, names));
    events.push({
      type: "action.requested",
      stepId,
      actionId: action.id,
      actionType: action.type,
      parameters: action.parameters,
      scripted: true,
      ...(deviation ? { deviation } : {}),
    });
    // Blocks the wizard carries out alone finish as they start.
    if (action.type === "wizard_instruction") events.push({ type: "action.completed", actionId: action.id });
    if (action.type === "end_trial") {
      events.push({ type: "action.completed", actionId: action.id }, { type: "trial.completed" });
      break;
    }
  }
  return ok(...events);
}

function skip(protocol: TrialProtocol, state: TrialState, actionId: string | undefined): Decision {
  const targets = actionId ? [findAction(protocol, actionId)?.action] : nextUnit(protocol, state);
  const stepId = state.currentStepId!;
  const events: EngineEvent[] = [];
  for (const action of targets) {
    if (!action || findAction(protocol, action.id)!.step.id !== stepId)
      return no("Only actions of the current step can be skipped.");
    if (state.actions[action.id]?.status !== "waiting") return no(`"${actionName(action)}" has already run.`);
    events.push({ type: "action.skipped", stepId, actionId: action.id, deviation: "skipped" });
  }
  if (events.length === 0) return no("Nothing is left to skip in this step.");
  return ok(...events);
}

function answer(protocol: TrialProtocol, state: TrialState, actionId: string, optionId: string): Decision {
  const found = findAction(protocol, actionId);
  if (!found || found.action.type !== "record_answer") return no("That is not a question of this protocol.");
  if (found.step.id !== state.currentStepId)
    return no(`That question belongs to "${found.step.name}", not the current step.`);
  if (state.actions[actionId]?.status !== "waiting") return no("The answer to this question is already recorded.");
  const option = answerOptions(found.action).find((o) => o.id === optionId);
  if (!option) return no(`"${optionId}" is not one of this question's answers.`);
  const inTurn = nextUnit(protocol, state).some((a) => a.id === actionId);
  const stepId = found.step.id;
  const events: EngineEvent[] = [
    {
      type: "answer.recorded",
      stepId,
      actionId,
      optionId,
      label: option.label,
      ...(inTurn ? {} : { deviation: "out_of_order" as const }),
    },
  ];
  // A branch right after the question resolves from the answer by itself.
  const actions = found.step.actions;
  const branch = actions[actions.indexOf(found.action) + 1];
  if (branch?.type === "branch" && state.actions[branch.id]?.status === "waiting") {
    const target = branchTarget(branch, optionId);
    if (target && findStep(protocol, target)) {
      events.push(
        { type: "branch.resolved", stepId, actionId: branch.id, optionId, targetStepId: target },
        { type: "step.entered", stepId: target, via: "branch" },
      );
    }
  }
  return ok(...events);
}

export type RobotReportCommand = Extract<
  Command,
  { kind: "dispatched" | "completed" | "failed" | "not_sent" | "unknown" | "timed_out" }
>;

/**
 * Reports of the robot's side that came together (a completion right after
 * its dispatch), each decided as if the ones before it were in the log
 * already: the events of those accepted, in order, to be written as one.
 * A refused report (on an action already finished) is left out, as alone.
 * It reads the reported actions only: no copy of every action of the trial.
 */
export function decideReports(
  protocol: TrialProtocol,
  state: TrialState,
  reports: readonly RobotReportCommand[],
): EngineEvent[] {
  const seen: TrialState = { ...state, actions: {} };
  const events: EngineEvent[] = [];
  for (const report of reports) {
    const action = seen.actions[report.actionId] ?? state.actions[report.actionId];
    if (action) seen.actions[report.actionId] = action;
    const decision = robotReport(seen, report);
    if (!decision.ok) continue;
    events.push(...decision.events);
    applyInPlace(
      seen,
      decision.events.map((event) => ({ ...event, seq: state.lastSeq, relMs: null })),
    );
  }
  // A question's clock starts once the actions before it are reported done.
  return events.length ? withTimers(protocol, state, events) : events;
}

/**
 * A command, and the robot's reports that came before it and wait for their
 * append: the reports' events first (they happened first), then the
 * command's, decided as if the reports' were in the log already (a pause
 * reported over lets the wizard go on). The reports' events stand even when
 * the command is refused.
 */
export function decideAfterReports(
  protocol: TrialProtocol,
  state: TrialState,
  reports: readonly RobotReportCommand[],
  command: Command,
  names: EventNames = NO_EVENT_NAMES,
): { reports: EngineEvent[]; decision: Decision } {
  const logged = reports.length ? decideReports(protocol, state, reports) : [];
  return {
    reports: logged,
    decision: decide(protocol, logged.length ? readThrough(state, logged) : state, command, names),
  };
}

function robotReport(state: TrialState, command: RobotReportCommand): Decision {
  const action = state.actions[command.actionId];
  if (!action || action.status === "waiting") return no("The robot reported on an action that was never requested.");
  // Sent, outcome unknown: the robot's own later word on it (its completion topic) is logged against it.
  if (action.status === "unknown" && command.kind === "completed")
    return ok({
      type: "action.completed",
      actionId: command.actionId,
      ...(command.detail ? { detail: command.detail } : {}),
    });
  if (FINISHED.has(action.status)) return no("The robot reported on an action that has already finished.");
  switch (command.kind) {
    case "dispatched":
      if (action.status !== "requested") return no("That action was already dispatched.");
      return ok({
        type: "action.dispatched",
        actionId: command.actionId,
        ...(command.detail ? { detail: command.detail } : {}),
      });
    case "completed":
      return ok({
        type: "action.completed",
        actionId: command.actionId,
        ...(command.detail ? { detail: command.detail } : {}),
      });
    case "failed":
      return ok({ type: "action.failed", actionId: command.actionId, reason: command.reason });
    case "not_sent":
      return ok({ type: "action.not_sent", actionId: command.actionId, reason: command.reason });
    case "unknown":
      return ok({ type: "action.unknown", actionId: command.actionId, reason: command.reason });
    case "timed_out":
      return ok({ type: "action.timed_out", actionId: command.actionId });
  }
}

/** The protocol's end: a step that leads to the end, with nothing left waiting. */
function reachedEnd(protocol: TrialProtocol, state: TrialState): boolean {
  const current = findStep(protocol, state.currentStepId);
  if (!current || exitNow(protocol, state, current.index).to === "step") return false;
  return current.step.actions.every((a) => state.actions[a.id]?.status !== "waiting");
}
