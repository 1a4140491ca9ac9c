"use client";
import { useEffect, useState } from "react";

/** Time since the trial's t0, ticking. */
export function TrialClock({ startedAt, stopped }: { startedAt: string | null; stopped: boolean }) {
  const [now, setNow] = useState(() => Date.now());
  useEffect(() => {
    if (!startedAt || stopped) return;
    const timer = setInterval(() => setNow(Date.now()), 250);
    return () => clearInterval(timer);
  }, [startedAt, stopped]);
  const seconds = startedAt ? Math.max(0, Math.floor((now - Date.parse(startedAt)) / 1000)) : 0;
  const text = `${String(Math.floor(seconds / 60)).padStart(2, "0")}:${String(seconds % 60).padStart(2, "0")}`;
  return (
    <span className="font-mono text-2xl tabular-nums" aria-label="Time since the trial started" role="timer">
      {text}
    </span>
  );
}
