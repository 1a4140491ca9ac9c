// The trial engine's vocabulary: the protocol it runs, the events it writes,
// the commands it accepts, and the state it folds events into.

import type { TrialProtocol } from "../protocol/document";
import type { Sensed } from "../plugins/types";

export type { TrialProtocol };

export type ProtocolAction = TrialProtocol["steps"][number]["actions"][number];

/** Blocks that steer the trial rather than move the robot. */
export const CONTROL_TYPES = [
  "record_answer",
  "branch",
  "end_trial",
  "wizard_instruction",
  "pause",
  "wait_for",
] as const;

export const DEVIATION_KINDS = ["skipped", "out_of_order", "unscripted", "manual_jump", "ended_early"] as const;
export type DeviationKind = (typeof DEVIATION_KINDS)[number];

export const TRIAL_STATUSES = ["scheduled", "in_progress", "paused", "completed", "aborted"] as const;
export type TrialStatus = (typeof TRIAL_STATUSES)[number];
/** A live trial: started and not ended; its robot is taken. */
export const LIVE_STATUSES = ["in_progress", "paused"] as const satisfies readonly TrialStatus[];
/** A trial not ended: scheduled or live. */
export const OPEN_STATUSES = ["scheduled", ...LIVE_STATUSES] as const satisfies readonly TrialStatus[];

export type EventBody =
  | { type: "trial.started" }
  | {
      type: "step.entered";
      stepId: string;
      /** "loop": back round a loop, under its bound; "loop_bound": its bound reached, its "onward" taken. */
      via: "start" | "next" | "branch" | "manual_jump" | "timeout" | "loop" | "loop_bound" | "sensed" | "go_on";
      /** The loop's name (../trial/loops.ts), when a loop moved the trial. */
      loop?: string;
    }
  | {
      type: "action.requested";
      stepId: string | null;
      actionId: string;
      actionType: string;
      parameters: Record<string, unknown>;
      scripted: boolean;
    }
  | { type: "action.dispatched"; actionId: string; detail?: Record<string, unknown> }
  | { type: "action.completed"; actionId: string; detail?: Record<string, unknown> }
  | { type: "action.failed"; actionId: string; reason: string }
  /** Dropped before it left the runtime (too old, stopped, the robot unreached): the robot never got it. */
  | { type: "action.not_sent"; actionId: string; reason: string }
  /** Left for the robot, and the link was lost before an outcome: it may still happen. */
  | { type: "action.unknown"; actionId: string; reason: string }
  | { type: "action.timed_out"; actionId: string }
  | { type: "action.skipped"; stepId: string; actionId: string }
  | { type: "answer.recorded"; stepId: string; actionId: string; optionId: string; label: string }
  | { type: "branch.resolved"; stepId: string; actionId: string; optionId: string; targetStepId: string }
  /** A time limit's clock began: a step's (from its entry), or a question's (actionId: once the actions before it are done). */
  | { type: "timer.started"; timerId: string; stepId: string; actionId?: string; seconds: number }
  /** Its time ran out: the trial takes the limit's way on, in the same append. */
  | { type: "timer.fired"; timerId: string }
  /** The wizard acted first (an answer, or the trial left the step or ended): it will never fire. */
  | { type: "timer.cancelled"; timerId: string }
  /** A loop has gone back its `times`: the trial leaves the step `stepId` by the loop's "onward", in the same append. */
  | { type: "loop.bound_reached"; stepId: string; loop: string; times: number }
  | { type: "trial.paused" }
  | { type: "trial.resumed" }
  | { type: "trial.emergency_stop" }
  | { type: "trial.aborted"; reason: string }
  | { type: "trial.completed" }
  | { type: "note.added"; text: string }
  /** A recording of the session began `offsetMs` after t0 (negative: before it), as its recorder measured. */
  | { type: "recording.started"; recordingId: string; offsetMs: number }
  /**
   * The robot sensed one of its plugin's events: `at` is the robot's own time (ms since the epoch), `message`
   * the one that matched. Logged whether or not a wait takes it; when none does, it is an observation only.
   */
  | ({ type: "robot.sensed" } & Sensed)
  /** A "Wait for" ended: by the robot's event (`event`, the wait's own entry `optionId`), or by the wizard's go on. */
  | {
      type: "wait.resolved";
      stepId: string;
      actionId: string;
      by: "sensed" | "wizard";
      event?: string;
      optionId?: string;
    }
  /** An error or warning the robot's side reported (a refused subscription, a status frame), in its words. */
  | { type: "robot.problem"; text: string };

/** An event as the engine produces it; the runtime adds seq, times and actor. */
export type EngineEvent = EventBody & { deviation?: DeviationKind };

/** An event as stored: what the fold reads. */
export type TrialEvent = EngineEvent & { seq: number; relMs: number | null };

/**
 * An event as the log keeps it, with its trial, server time and actor. The
 * database gives the time as a Date; the socket carries it as an ISO string
 * (`StoredEvent<string>`).
 */
export type StoredEvent<Time extends Date | string = Date> = TrialEvent & {
  trialId: string;
  serverTime: Time;
  actorId: string | null;
};

/** An emergency stop or an abort: the robot is stopped at once, ahead of every command waiting to be logged. */
export function haltsTheRobot(kind: string): boolean {
  return kind === "emergency_stop" || kind === "abort";
}

export type Command =
  | { kind: "start" }
  | { kind: "next" }
  | { kind: "skip"; actionId?: string }
  | { kind: "trigger"; actionId: string }
  | { kind: "answer"; actionId: string; optionId: string }
  /** The wizard ends the pending "Wait for" without the robot's event: the protocol's default way on, not a deviation. */
  | { kind: "go_on" }
  | { kind: "jump"; stepId: string }
  | { kind: "unscripted"; actionId: string; actionType: string; parameters: Record<string, unknown> }
  | { kind: "pause" }
  | { kind: "resume" }
  | { kind: "abort"; reason: string }
  | { kind: "complete" }
  | { kind: "emergency_stop" }
  | { kind: "note"; text: string }
  | { kind: "recording"; recordingId: string; offsetMs: number }
  // What the robot side (or the clock, for pauses) reports back.
  | { kind: "dispatched"; actionId: string; detail?: Record<string, unknown> }
  | { kind: "completed"; actionId: string; detail?: Record<string, unknown> }
  | { kind: "failed"; actionId: string; reason: string }
  | { kind: "not_sent"; actionId: string; reason: string }
  | { kind: "unknown"; actionId: string; reason: string }
  | { kind: "timed_out"; actionId: string }
  | { kind: "robot_problem"; text: string }
  | ({ kind: "sensed" } & Sensed)
  // The runtime's clock: a timer's time ran out.
  | { kind: "timer_fired"; timerId: string };

export type ActionStatus =
  | "waiting"
  | "requested"
  | "running"
  | "done"
  | "failed"
  | "not_sent"
  | "unknown"
  | "timed_out"
  | "skipped";

export interface ActionState {
  status: ActionStatus;
  requestedAt: number | null;
  finishedAt: number | null;
}

export interface TrialState {
  status: TrialStatus;
  emergencyStopped: boolean;
  currentStepId: string | null;
  /** Scripted and unscripted actions by id. */
  actions: Record<string, ActionState>;
  answers: Record<string, string>;
  /** The steps entered so far, in order: the path this trial took. */
  path: string[];
  /** Each step's actions, so a step entered again runs them again. */
  stepActions: Record<string, string[]>;
  /** The timers running now (started, neither fired nor cancelled), by id, with when they started. */
  timers: Record<string, RunningTimer>;
  /** When the trial was paused (or stopped), in ms from t0, while it is: the timers' clocks stand still from then. */
  pausedAtMs: number | null;
  /** How many times each loop has gone back so far, by its name. */
  loops: Record<string, number>;
  lastSeq: number;
}

export interface RunningTimer {
  stepId: string;
  /** The question it waits on; absent for a step's time limit. */
  actionId?: string;
  seconds: number;
  /** When it started, in ms from the trial's t0 (null in a log without times). */
  startedMs: number | null;
  /** How long the trial was paused since it started, in ms: not counted against its limit. */
  pausedMs: number;
}

export type Decision = { ok: true; events: EngineEvent[] } | { ok: false; reason: string };
