// "Wait for": the step holds until the robot senses one of the listed events
// (each leads its own way), its time limit runs out (./timers.ts), or the
// wizard goes on. Whichever reaches the log first ends the wait; what comes
// after finds nothing waiting: an event is then the robot's observation only,
// a go on is refused, a timer is already cancelled.
import { awaitedEvents, exitBy, exitOf, type Exit } from "../protocol/flow";
import { type EventNames, eventName } from "../plugins/event-names";
import { findStep } from "./protocol";
import { awaits } from "./timers";
import type { Command, Decision, EngineEvent, ProtocolAction, TrialProtocol, TrialState } from "./types";

/** The "Wait for" the current step holds on now, if any. */
export function pendingWait(protocol: TrialProtocol, state: TrialState): ProtocolAction | null {
  if (state.status !== "in_progress") return null;
  const current = findStep(protocol, state.currentStepId);
  if (!current) return null;
  const { step } = current;
  const index = step.actions.findIndex((a, i) => a.type === "wait_for" && awaits(step, i, state));
  return index < 0 ? null : step.actions[index]!;
}

/** The robot sensed something: always logged; it moves the trial only along a pending wait's edge for that event. */
export function sensed(
  protocol: TrialProtocol,
  state: TrialState,
  command: Extract<Command, { kind: "sensed" }>,
): Decision {
  if (state.status === "completed" || state.status === "aborted")
    return { ok: false, reason: "This trial has already ended." };
  const { event, at, message } = command;
  const observed: EngineEvent = { type: "robot.sensed", event, at, message };
  const wait = pendingWait(protocol, state);
  const edge = wait && awaitedEvents(wait).find((e) => e.event === event);
  if (!wait || !edge) return { ok: true, events: [observed] };
  const stepId = state.currentStepId!;
  const index = findStep(protocol, stepId)!.index;
  return {
    ok: true,
    events: [
      observed,
      { type: "wait.resolved", stepId, actionId: wait.id, by: "sensed", event, optionId: edge.id },
      ...enter(protocol, exitBy(protocol.steps, index, edge.after), "sensed"),
    ],
  };
}

/**
 * The wizard's go on: the wait's default way on, the block's "otherwise". The
 * trial carries on with what follows the block in its step; when nothing does,
 * it takes the step's own way on at once.
 */
export function goOn(protocol: TrialProtocol, state: TrialState): Decision {
  const wait = pendingWait(protocol, state);
  if (!wait) return { ok: false, reason: "Nothing is waiting for the robot now: the wait is already over." };
  const stepId = state.currentStepId!;
  const { step, index } = findStep(protocol, stepId)!;
  const resolved: EngineEvent = { type: "wait.resolved", stepId, actionId: wait.id, by: "wizard" };
  const rest = step.actions.slice(step.actions.indexOf(wait) + 1);
  if (rest.some((a) => state.actions[a.id]?.status === "waiting")) return { ok: true, events: [resolved] };
  return { ok: true, events: [resolved, ...enter(protocol, exitOf(protocol.steps, index), "go_on")] };
}

function enter(protocol: TrialProtocol, exit: Exit, via: "sensed" | "go_on"): EngineEvent[] {
  // An edge to a step that is gone cannot be published; in a rehearsal it ends the trial, as a step's "after" does.
  if (exit.to !== "step") return [{ type: "trial.completed" }];
  return [{ type: "step.entered", stepId: protocol.steps[exit.index]!.id, via }];
}

/** What the wizard is told when "next" reaches a wait. */
export function waitingWords(wait: ProtocolAction, names: EventNames): string {
  const events = awaitedEvents(wait).map((e) => `“${eventName(e.event, names)}”`);
  const what = events.length ? `the robot to sense ${events.join(" or ")}` : "its time limit";
  return `The trial waits for ${what}: go on to move on without it.`;
}
