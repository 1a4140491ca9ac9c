"use client";
// The time limits running now, counting down on the wizard's page: how long
// is left and where the trial goes then. The wizard can always act first;
// the runtime fires them, this only shows them. While the trial is paused
// their clocks stand still, and so does the countdown.
import { useEffect, useState } from "react";
import { remainingMs, timerExit, type TrialProtocol, type TrialState } from "@/core/trial";

export function TimeLimits({
  protocol,
  state,
  startedAt,
}: {
  protocol: TrialProtocol;
  state: TrialState;
  startedAt: string | null;
}) {
  const [now, setNow] = useState(() => Date.now());
  const running = Object.entries(state.timers);
  const ticking = running.length > 0 && state.status === "in_progress";
  useEffect(() => {
    if (!ticking) return;
    // From now on resuming, not from the last tick before the pause.
    setNow(Date.now());
    const timer = setInterval(() => setNow(Date.now()), 250);
    return () => clearInterval(timer);
  }, [ticking]);
  if (!startedAt || running.length === 0) return null;
  const t0 = Date.parse(startedAt);
  return (
    <ul aria-label="Time limits" className="space-y-1 text-sm">
      {running.map(([timerId, timer]) => {
        const ms = remainingMs(timer, state, now - t0);
        const left = ms === null ? null : Math.ceil(ms / 1000);
        return (
          <li key={timerId} className="rounded border border-amber-300 bg-amber-50 px-3 py-2 text-amber-900">
            {timer.actionId
              ? isWait(protocol, timer.actionId)
                ? "Nothing sensed in"
                : "No answer in"
              : "Step time left:"}{" "}
            <span role="timer" className="font-mono tabular-nums" data-testid="time-left">
              {left === null ? `${timer.seconds}` : left} s
            </span>{" "}
            → {whereTo(protocol, timer, state)}
          </li>
        );
      })}
    </ul>
  );
}

function isWait(protocol: TrialProtocol, actionId: string): boolean {
  return protocol.steps.some((s) => s.actions.some((a) => a.id === actionId && a.type === "wait_for"));
}

function whereTo(protocol: TrialProtocol, timer: TrialState["timers"][string], state: TrialState): string {
  const exit = timerExit(protocol, timer, state);
  return exit.to === "step" ? `“${protocol.steps[exit.index]!.name}”` : "the end of the trial";
}
