// Trial state is a fold over the trial's events: the live view, resume after
// a crash, replay and reports all start here. Folding is linear in events:
// a batch copies the state once and then changes the copy in place, so a
// trial of 100k events (most of them unscripted lines, each its own action)
// never copies its growing map of actions once per event.
import type { ActionStatus, EngineEvent, TrialEvent, TrialProtocol, TrialState } from "./types";

const WAITING = { status: "waiting", requestedAt: null, finishedAt: null } as const;

export function initialState(protocol: TrialProtocol): TrialState {
  const actions: TrialState["actions"] = {};
  const stepActions: TrialState["stepActions"] = {};
  for (const step of protocol.steps) {
    for (const action of step.actions) actions[action.id] = WAITING;
    stepActions[step.id] = step.actions.map((a) => a.id);
  }
  return {
    status: "scheduled",
    emergencyStopped: false,
    currentStepId: null,
    actions,
    answers: {},
    path: [],
    stepActions,
    timers: {},
    pausedAtMs: null,
    loops: {},
    lastSeq: 0,
  };
}

/** The state after `events`; `state` itself is left as it was. */
export function applyAll(state: TrialState, events: readonly TrialEvent[]): TrialState {
  const next: TrialState = {
    ...state,
    actions: { ...state.actions },
    answers: { ...state.answers },
    path: [...state.path],
    timers: { ...state.timers },
    loops: { ...state.loops },
  };
  for (const event of events) advance(next, event);
  return next;
}

/**
 * `state` itself moved on by `events`, in place: for the one owner of a live
 * state (the runtime's trial host), whose cost per command must not grow with
 * the trial, as a copy of every action so far would.
 */
export function applyInPlace(state: TrialState, events: readonly TrialEvent[]): void {
  for (const event of events) advance(state, event);
}

/**
 * The state after `events` decided but not yet stored (no seq, no time), for a decision to read. It reads
 * through to `state`'s actions rather than copy them all: the live host's cost per command must not grow
 * with the trial. `state` itself is left as it was.
 */
export function readThrough(state: TrialState, events: readonly EngineEvent[]): TrialState {
  const after: TrialState = {
    ...state,
    actions: Object.create(state.actions),
    answers: { ...state.answers },
    path: [...state.path],
    timers: { ...state.timers },
    loops: { ...state.loops },
  };
  applyInPlace(
    after,
    events.map((event) => ({ ...event, seq: state.lastSeq, relMs: null })),
  );
  return after;
}

export function apply(state: TrialState, event: TrialEvent): TrialState {
  return applyAll(state, [event]);
}

export function fold(protocol: TrialProtocol, events: readonly TrialEvent[]): TrialState {
  return applyAll(initialState(protocol), events);
}

/** What each action event makes of its action, and which time it stamps. */
const ACTION_OUTCOME: Partial<Record<TrialEvent["type"], [ActionStatus, "requestedAt" | "finishedAt" | null]>> = {
  "action.requested": ["requested", "requestedAt"],
  "action.dispatched": ["running", null],
  "action.completed": ["done", "finishedAt"],
  "action.failed": ["failed", "finishedAt"],
  "action.not_sent": ["not_sent", "finishedAt"],
  "action.unknown": ["unknown", "finishedAt"],
  "action.timed_out": ["timed_out", "finishedAt"],
  "action.skipped": ["skipped", "finishedAt"],
  "answer.recorded": ["done", "finishedAt"],
  "branch.resolved": ["done", "finishedAt"],
  "wait.resolved": ["done", "finishedAt"],
};

/**
 * Moves a state that only the caller holds on by one event, in place. Each
 * action's entry is replaced, never changed, so a state copied by `applyAll`
 * shares entries with the one it came from safely.
 */
function advance(next: TrialState, event: TrialEvent): void {
  next.lastSeq = event.seq;
  const outcome = ACTION_OUTCOME[event.type];
  // A timer's actionId names the question it waits on: its events leave the action as it is.
  if (outcome && "actionId" in event && event.actionId !== undefined) {
    const [status, field] = outcome;
    const before = next.actions[event.actionId] ?? WAITING;
    next.actions[event.actionId] = { ...before, status, ...(field ? { [field]: event.relMs } : {}) };
  }
  switch (event.type) {
    case "trial.resumed":
      resumeClocks(next, event.relMs);
      next.status = "in_progress";
      next.emergencyStopped = false;
      break;
    case "trial.started":
      next.status = "in_progress";
      next.emergencyStopped = false;
      break;
    case "step.entered":
      // A step entered again (a loop back, or the wizard's jump) runs its actions again.
      if (next.path.includes(event.stepId))
        for (const id of next.stepActions[event.stepId] ?? []) next.actions[id] = WAITING;
      next.currentStepId = event.stepId;
      next.path.push(event.stepId);
      if (event.via === "loop" && event.loop) next.loops[event.loop] = (next.loops[event.loop] ?? 0) + 1;
      break;
    case "answer.recorded":
      next.answers[event.actionId] = event.optionId;
      break;
    case "timer.started": {
      const { timerId, stepId, actionId, seconds } = event;
      next.timers[timerId] = {
        stepId,
        ...(actionId ? { actionId } : {}),
        seconds,
        startedMs: event.relMs,
        pausedMs: 0,
      };
      break;
    }
    case "timer.fired":
    case "timer.cancelled":
      delete next.timers[event.timerId];
      break;
    case "trial.paused":
      next.status = "paused";
      next.pausedAtMs ??= event.relMs;
      break;
    case "trial.emergency_stop":
      next.status = "paused";
      // A stop during a pause: the clocks stood still from the pause already.
      next.pausedAtMs ??= event.relMs;
      next.emergencyStopped = true;
      break;
    case "trial.aborted":
      next.status = "aborted";
      break;
    case "trial.completed":
      next.status = "completed";
      break;
  }
}

/**
 * The trial resumed at `resumedMs`: each running timer's clock goes on from
 * what it had left, the time paused added to its `pausedMs` (for one started
 * during the pause, the time since it started). New timer objects, as
 * `next.timers` is a copy whose timers may be shared with the state before.
 */
function resumeClocks(next: TrialState, resumedMs: number | null) {
  const pausedAt = next.pausedAtMs;
  next.pausedAtMs = null;
  if (pausedAt === null || resumedMs === null) return;
  for (const [timerId, timer] of Object.entries(next.timers)) {
    const held = resumedMs - Math.max(pausedAt, timer.startedMs ?? pausedAt);
    next.timers[timerId] = { ...timer, pausedMs: timer.pausedMs + held };
  }
}
