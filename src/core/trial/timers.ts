// Time limits as the engine keeps them. Which timers run is a reading of the
// state (the current step's limit; a question's, once the actions before it
// are done), so every decision ends by starting the timers its events made
// due and cancelling those they ended: the wizard acting first cancels a
// timer in the same append, and a cancelled or fired timer never fires.
import { type Exit, exitBy, TIMED_BLOCKS } from "../protocol/flow";
import { readThrough } from "./fold";
import { follow, loopName, timesTaken } from "./loops";
import { findAction, findStep } from "./protocol";
import type { Decision, EngineEvent, RunningTimer, TrialProtocol, TrialState } from "./types";

export const FINISHED = new Set(["done", "failed", "not_sent", "unknown", "timed_out", "skipped"]);

type DueTimer = Omit<RunningTimer, "startedMs" | "pausedMs">;

/** Whether the step's action at `index` is what the step waits on now: still waiting, every action before it finished. */
export function awaits(step: TrialProtocol["steps"][number], index: number, state: TrialState): boolean {
  const status = (id: string) => state.actions[id]?.status ?? "waiting";
  if (status(step.actions[index]!.id) !== "waiting") return false;
  return step.actions.slice(0, index).every((before) => FINISHED.has(status(before.id)));
}

/** The timers `state` should have running, by id; an id names the step's visit, so a step entered again starts anew. */
export function timersDue(protocol: TrialProtocol, state: TrialState): Map<string, DueTimer> {
  const due = new Map<string, DueTimer>();
  if (state.status !== "in_progress" && state.status !== "paused") return due;
  const current = findStep(protocol, state.currentStepId);
  if (!current) return due;
  const { step } = current;
  const visit = state.path.length;
  if (step.timeLimit) due.set(`step:${step.id}:${visit}`, { stepId: step.id, seconds: step.timeLimit.seconds });
  step.actions.forEach((action, i) => {
    if (!TIMED_BLOCKS.has(action.type) || !action.timeLimit || !awaits(step, i, state)) return;
    due.set(`${action.type === "wait_for" ? "wait" : "answer"}:${action.id}:${visit}`, {
      stepId: step.id,
      actionId: action.id,
      seconds: action.timeLimit.seconds,
    });
  });
  return due;
}

/**
 * When a running timer is due, in ms from t0, unless the trial is paused
 * again: its start, its limit and the time paused since it started. Null in a
 * log without times.
 */
export function dueMs(timer: RunningTimer): number | null {
  return timer.startedMs === null ? null : timer.startedMs + timer.pausedMs + timer.seconds * 1000;
}

/**
 * How long a running timer has left at `nowMs` (from t0). While the trial is
 * paused its clock stands still: what it had left as the pause began (all of
 * it, for one started during the pause).
 */
export function remainingMs(timer: RunningTimer, state: TrialState, nowMs: number): number | null {
  const due = dueMs(timer);
  if (due === null) return null;
  if (state.pausedAtMs === null) return Math.max(0, due - nowMs);
  return Math.max(0, Math.min(timer.seconds * 1000, due - state.pausedAtMs));
}

/** `events` (decided on `state`) followed by the timers they cancel and start. */
export function withTimers(protocol: TrialProtocol, state: TrialState, events: EngineEvent[]): EngineEvent[] {
  const after = readThrough(state, events);
  const due = timersDue(protocol, after);
  const cancelled: EngineEvent[] = Object.keys(after.timers)
    .filter((timerId) => !due.has(timerId))
    .map((timerId) => ({ type: "timer.cancelled", timerId }));
  const started: EngineEvent[] = [...due]
    .filter(([timerId]) => !(timerId in after.timers))
    .map(([timerId, timer]) => ({ type: "timer.started", timerId, ...timer }));
  return [...events, ...cancelled, ...started];
}

/** The loop name of a timer's limit (if its "after" is a loop). */
function timerLoop(timer: RunningTimer): string {
  return loopName(timer.stepId, timer.actionId ? { of: "answer", actionId: timer.actionId } : { of: "step" });
}

function limitOf(protocol: TrialProtocol, timer: RunningTimer) {
  const at = findStep(protocol, timer.stepId);
  const limit = timer.actionId ? findAction(protocol, timer.actionId)?.action.timeLimit : at?.step.timeLimit;
  return at && limit ? { index: at.index, after: limit.after } : null;
}

/** Where a timer leads when its time runs out: its limit's "after", read from its step (a loop: as `state` has gone round it). */
export function timerExit(protocol: TrialProtocol, timer: RunningTimer, state: TrialState): Exit {
  const limit = limitOf(protocol, timer);
  return limit ? exitBy(protocol.steps, limit.index, limit.after, timesTaken(state, timerLoop(timer))) : { to: "end" };
}

/** A timer's time ran out: the trial takes its limit's way on, unless the wizard acted first. */
export function timerFired(protocol: TrialProtocol, state: TrialState, timerId: string): Decision {
  const timer = state.timers[timerId];
  if (!timer) return { ok: false, reason: "That timer is no longer running: the wizard acted first, or it fired." };
  const limit = limitOf(protocol, timer);
  const fired: EngineEvent = { type: "timer.fired", timerId };
  if (!limit) return { ok: true, events: [fired, { type: "trial.completed" }] };
  return {
    ok: true,
    events: [fired, ...follow(protocol, state, limit.index, limit.after, timerLoop(timer), "timeout")],
  };
}
