"use client";
// The robot's joint angles over the trial, one line per joint, on the
// timeline's time axis: the same playhead shows where the recording is, and a
// click seeks it there, as on the timeline.
import { Card } from "@/ui/surface";

// Dark enough for the legend's text on white (WCAG AA, 4.5:1).
const COLOURS = ["#2458b8", "#b45309", "#047857", "#b91c1c", "#7c3aed"];

export function JointAngles({
  samples,
  endMs,
  playheadMs,
  onSeek,
}: {
  samples: Array<{ relMs: number; data: unknown }>;
  /** The timeline's end: both share one time axis. */
  endMs: number;
  playheadMs: number | null;
  onSeek: (ms: number) => void;
}) {
  const rows = samples.map((s) => ({ t: s.relMs, ...(s.data as { name: string[]; position: number[] }) }));
  const names = rows[0]?.name ?? [];
  // Loops, not spreads: a long trial has more samples than a function may take arguments.
  let tMax = Math.max(1, endMs);
  let lo = -0.1;
  let hi = 0.1;
  for (const r of rows) {
    tMax = Math.max(tMax, r.t);
    for (const v of r.position) {
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    }
  }
  const x = (t: number) => (t / tMax) * 1000;
  const y = (v: number) => 180 - ((v - lo) / (hi - lo)) * 170;
  return (
    <section aria-label="Joint angles">
      <h2 className="mb-2 text-lg font-semibold">Robot joint angles</h2>
      <Card className="p-4">
        {/* biome-ignore lint/a11y/useKeyWithClickEvents: a click seeks, for the mouse; the timeline's bars and the events list do it from the keyboard */}
        <svg
          viewBox="0 0 1000 190"
          preserveAspectRatio="none"
          className="h-48 w-full cursor-pointer"
          role="img"
          aria-label={`Joint angles of ${names.join(", ")} over ${(tMax / 1000).toFixed(0)} s`}
          onClick={(e) => {
            const box = e.currentTarget.getBoundingClientRect();
            onSeek(((e.clientX - box.left) / box.width) * tMax);
          }}
        >
          {names.map((name, j) => (
            <polyline
              key={name}
              fill="none"
              stroke={COLOURS[j % COLOURS.length]}
              strokeWidth="2"
              points={rows.map((r) => `${x(r.t).toFixed(1)},${y(r.position[j] ?? 0).toFixed(1)}`).join(" ")}
            />
          ))}
          {playheadMs !== null && (
            <line
              data-testid="samples-playhead"
              x1={x(playheadMs)}
              x2={x(playheadMs)}
              y1={0}
              y2={190}
              stroke="#dc2626"
              strokeWidth="2"
              vectorEffect="non-scaling-stroke"
            />
          )}
        </svg>
        <div className="mt-2 flex flex-wrap gap-4 text-xs">
          {names.map((name, j) => (
            <span key={name} style={{ color: COLOURS[j % COLOURS.length] }}>
              ● {name}
            </span>
          ))}
        </div>
      </Card>
    </section>
  );
}
