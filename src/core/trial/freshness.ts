// How long a wizard's command stays worth carrying out, counted from the
// moment the wizard asked (the page's clock, brought onto the runtime's by
// the connection's measured offset), not from when some hop read it: a line
// said 20 s after it was asked for, in the middle of something else, is
// worse than one not said and told so. Every hop (the runtime's queue,
// forwarding to the owner, the robot link before it sends) asks `staleness`
// and drops what is too old. Emergency stop and abort have no limit: a stop
// late is still a stop.
import type { Command } from "./types";

/** A robot action: a few seconds, the most a wizard's timing can slip and still make sense. */
export const ROBOT_ACTION_FRESH_MS = 3000;

/** Each command kind's freshness limit in ms; null: no limit. The robot's and the clock's reports are facts, never stale. */
export const FRESH_FOR_MS: Record<Command["kind"], number | null> = {
  start: ROBOT_ACTION_FRESH_MS,
  next: ROBOT_ACTION_FRESH_MS,
  trigger: ROBOT_ACTION_FRESH_MS,
  answer: ROBOT_ACTION_FRESH_MS,
  jump: ROBOT_ACTION_FRESH_MS,
  unscripted: ROBOT_ACTION_FRESH_MS,
  resume: ROBOT_ACTION_FRESH_MS,
  skip: null,
  // Ends a wait and moves no robot, as a skip: the first of it and an event to reach the log decides the race.
  go_on: null,
  pause: null,
  complete: null,
  emergency_stop: null,
  abort: null,
  note: null,
  recording: null,
  dispatched: null,
  completed: null,
  failed: null,
  not_sent: null,
  unknown: null,
  timed_out: null,
  robot_problem: null,
  sensed: null,
  // The runtime's own clock: a timer fires when it was due, however late the process got to it.
  timer_fired: null,
};

/** A page clock this far from the runtime's, once the offset is taken off, is not believed. */
export const CLOCK_TOLERANCE_MS = 1000;

/**
 * When the wizard asked, on the runtime's clock: the page's time less the connection's offset. Without a
 * page time or a measured offset, when the runtime read it. A moment ahead of the runtime's clock (the
 * offset drifted) is taken as now; one further back than the tolerance allows beyond any limit is refused
 * with why, rather than guessed at.
 */
export function askedAt(
  pageTime: number | undefined,
  offsetMs: number | null,
  readAt: number,
): { ok: true; at: number } | { ok: false; reason: string } {
  if (pageTime === undefined || offsetMs === null) return { ok: true, at: readAt };
  const at = pageTime - offsetMs;
  if (at > readAt + CLOCK_TOLERANCE_MS)
    return {
      ok: false,
      reason: `Not carried out: this page's clock is ${Math.round((at - readAt) / 1000)} s ahead of what the runtime measured. Reload the page and ask again.`,
    };
  return { ok: true, at: Math.min(at, readAt) };
}

/** How old a command of `kind` asked at `at` is at `now`, if older than its limit; null while fresh. */
export function staleness(kind: Command["kind"], at: number, now: number) {
  return olderThan(FRESH_FOR_MS[kind], at, now);
}

/** How old something asked at `at` is at `now`, if older than `limitMs` (null: no limit); null while fresh. */
export function olderThan(limitMs: number | null, at: number, now: number): { ageMs: number; limitMs: number } | null {
  const ageMs = now - at;
  return limitMs !== null && ageMs > limitMs ? { ageMs, limitMs } : null;
}

/** Why a command was dropped at `where`, in the wizard's words. */
export function droppedReason(where: string, stale: { ageMs: number; limitMs: number }): string {
  return `Not sent: asked for ${(stale.ageMs / 1000).toFixed(1)} s ago, longer than the ${stale.limitMs / 1000} s it stays worth doing, so it was dropped at ${where} rather than done late. Ask again if you still want it.`;
}
