// Trial state is a fold over the trial's events: the live view, resume after
// a crash, replay and reports all start here.
import type { ActionStatus, TrialEvent, TrialProtocol, TrialState } from "./types";

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
    lastSeq: 0,
  };
}

export function apply(state: TrialState, event: TrialEvent): TrialState {
  const next: TrialState = { ...state, lastSeq: event.seq };
  const setAction = (id: string, status: ActionStatus, field: "requestedAt" | "finishedAt" | null) => {
    const before = next.actions[id] ?? WAITING;
    next.actions = { ...next.actions, [id]: { ...before, status, ...(field ? { [field]: event.relMs } : {}) } };
  };
  switch (event.type) {
    case "trial.started":
      return { ...next, status: "in_progress" };
    case "step.entered": {
      // A step entered again (a loop back, or the wizard's jump) runs its actions again.
      const again = next.path.includes(event.stepId);
      if (again) {
        next.actions = { ...next.actions };
        for (const id of next.stepActions[event.stepId] ?? []) next.actions[id] = WAITING;
      }
      return { ...next, currentStepId: event.stepId, path: [...next.path, event.stepId] };
    }
    case "action.requested":
      setAction(event.actionId, "requested", "requestedAt");
      return next;
    case "action.dispatched":
      setAction(event.actionId, "running", null);
      return next;
    case "action.completed":
      setAction(event.actionId, "done", "finishedAt");
      return next;
    case "action.failed":
      setAction(event.actionId, "failed", "finishedAt");
      return next;
    case "action.timed_out":
      setAction(event.actionId, "timed_out", "finishedAt");
      return next;
    case "action.skipped":
      setAction(event.actionId, "skipped", "finishedAt");
      return next;
    case "answer.recorded":
      setAction(event.actionId, "done", "finishedAt");
      return { ...next, answers: { ...next.answers, [event.actionId]: event.optionId } };
    case "branch.resolved":
      setAction(event.actionId, "done", "finishedAt");
      return next;
    case "trial.paused":
      return { ...next, status: "paused" };
    case "trial.resumed":
      return { ...next, status: "in_progress", emergencyStopped: false };
    case "trial.emergency_stop":
      return { ...next, status: "paused", emergencyStopped: true };
    case "trial.aborted":
      return { ...next, status: "aborted" };
    case "trial.completed":
      return { ...next, status: "completed" };
    case "note.added":
    case "recording.started":
      return next;
  }
}

export function fold(protocol: TrialProtocol, events: TrialEvent[]): TrialState {
  return events.reduce(apply, initialState(protocol));
}
