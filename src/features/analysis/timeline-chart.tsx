"use client";
// The trial at a glance, on one time axis under the video: step bands, action
// bars from requested to finished, deviations and annotations, and what of
// the trial the recording holds (with its gaps, and why). Clicking
// anything seeks the recording there; the playhead shows where it is.
// Steps and annotations are few (the protocol's, the researchers'): each is a
// button. Actions and deviations can be tens of thousands in a long trial:
// their lanes are drawn (one SVG path per colour) with one button that the
// arrow keys move from bar to bar.
import { useMemo, useState } from "react";
import { type FidelityReport, outcomeWords } from "@/core/analysis/fidelity";
import type { RecordingGap, RecordingPart } from "@/core/media/recording-parts";
import { cn } from "@/ui/cn";
import { seconds } from "@/ui/format";
import { Card } from "@/ui/surface";

interface Props {
  report: FidelityReport;
  deviations: Array<{ at: number; kind: string }>;
  annotations: Array<{ at: number; label: string }>;
  /** The recording's parts and the gaps between them; null when the trial has none. */
  recording: { parts: RecordingPart[]; gaps: RecordingGap[] } | null;
  endMs: number;
  playheadMs: number | null;
  onSeek: ((ms: number) => void) | null;
}

const BAND = ["bg-sky-100 text-sky-900", "bg-indigo-100 text-indigo-900"];

export function TimelineChart({ report, deviations, annotations, recording, endMs, playheadMs, onSeek }: Props) {
  const total = Math.max(1, endMs);
  // Thousands in a long trial: made once, not on every move of the playhead.
  const actionMarks = useMemo(
    (): Mark[] =>
      report.actions
        .filter((a) => a.requestedMs !== null)
        .map((a) => {
          const answered = a.answer === null ? "" : `, answered “${a.answer}”`;
          return {
            at: a.requestedMs!,
            to: a.requestedMs! + (a.durationMs ?? 0),
            tone: a.outcome === "executed" ? "executed" : a.outcome === "skipped" ? "skipped" : "failed",
            label: `Action ${a.name}${answered} at ${seconds(a.requestedMs)}`,
            title: `${a.name}: ${outcomeWords(a.outcome)}${answered}`,
          };
        }),
    [report.actions],
  );
  const deviationMarks = useMemo(
    () =>
      deviations.map(
        (d): Mark => ({
          at: d.at,
          to: d.at,
          tone: "deviation",
          label: `Deviation: ${d.kind.replace("_", " ")} at ${seconds(d.at)}`,
          title: d.kind.replace("_", " "),
        }),
      ),
    [deviations],
  );
  const left = (ms: number) => `${Math.min(100, Math.max(0, (ms / total) * 100))}%`;
  const width = (from: number, to: number) => `max(3px, ${Math.min(100, ((to - from) / total) * 100)}%)`;
  const seek = (ms: number) => onSeek?.(ms);
  const item =
    "absolute top-1 bottom-1 rounded-sm text-[10px] leading-4 overflow-hidden whitespace-nowrap px-0.5 text-left";
  // Clicking empty space seeks to that time too.
  const laneSeek = (e: React.MouseEvent<HTMLDivElement>) => {
    if (e.target !== e.currentTarget || !onSeek) return;
    const box = e.currentTarget.getBoundingClientRect();
    seek(((e.clientX - box.left) / box.width) * total);
  };
  const lane = (name: string, children: React.ReactNode) => (
    <div className="grid grid-cols-[6rem_1fr] items-center gap-2">
      <span className="text-xs text-slate-500">{name}</span>
      {/* biome-ignore lint/a11y/useKeyWithClickEvents: a click anywhere on the lane seeks, for the mouse; every bar in it is a button for the keyboard */}
      {/* biome-ignore lint/a11y/useSemanticElements: a group so that its name is read with the bars it holds (a plain div may not have a name); a fieldset is for form fields */}
      <div
        role="group"
        className={cn("relative h-6 rounded bg-slate-50", onSeek && "cursor-pointer")}
        onClick={laneSeek}
        aria-label={`${name} over time`}
      >
        {children}
      </div>
    </div>
  );
  return (
    <Card role="group" className="relative space-y-1.5 p-4" aria-label="Timeline chart">
      {lane(
        "Steps",
        report.steps
          .filter((s) => s.enteredMs !== null)
          .map((s, i) => (
            <button
              key={s.stepId}
              type="button"
              title={s.name}
              className={cn(item, BAND[i % 2])}
              style={{ left: left(s.enteredMs!), width: width(s.enteredMs!, s.leftMs ?? endMs) }}
              onClick={() => seek(s.enteredMs!)}
            >
              {s.name}
            </button>
          )),
      )}
      {lane("Actions", <DrawnMarks name="Action" total={total} onSeek={seek} marks={actionMarks} />)}
      {lane("Deviations", <DrawnMarks name="Deviation" total={total} onSeek={seek} marks={deviationMarks} />)}
      {lane(
        "Annotations",
        annotations.map((m, i) => (
          <button
            key={i}
            type="button"
            title={m.label}
            aria-label={`Annotation: ${m.label}`}
            className="absolute top-1 h-4 w-4 -translate-x-1/2 rotate-45 rounded-sm bg-violet-500"
            style={{ left: left(m.at) }}
            onClick={() => seek(m.at)}
          />
        )),
      )}
      {recording &&
        lane("Recording", [
          ...recording.parts.map((p) => (
            <div
              key={p.id}
              aria-hidden
              className="pointer-events-none absolute top-1 bottom-1 rounded-sm bg-slate-300"
              style={{
                left: left(p.offsetMs ?? 0),
                width: width(p.offsetMs ?? 0, (p.offsetMs ?? 0) + (p.durationMs ?? 0)),
              }}
            />
          )),
          ...recording.gaps.map((g) => (
            <button
              key={`gap-${g.fromMs}`}
              type="button"
              title={`Not recorded: ${g.cause}`}
              aria-label={`Not recorded from ${seconds(g.fromMs)} to ${seconds(g.toMs)}: ${g.cause}`}
              className="absolute top-1 bottom-1 rounded-sm border border-dashed border-red-700 bg-red-100"
              style={{ left: left(g.fromMs), width: width(g.fromMs, g.toMs) }}
              onClick={() => seek(g.toMs)}
            />
          )),
        ])}
      {playheadMs !== null && (
        <div
          className="pointer-events-none absolute inset-y-3 w-0.5 bg-red-600"
          data-testid="playhead"
          style={{
            left: `calc(1rem + 6rem + 0.5rem + (100% - 2rem - 6.5rem) * ${Math.min(1, Math.max(0, playheadMs / total))})`,
          }}
        />
      )}
    </Card>
  );
}

type Mark = { at: number; to: number; tone: keyof typeof FILL; label: string; title: string };

const FILL = {
  executed: "fill-emerald-300",
  skipped: "fill-amber-300",
  failed: "fill-red-300",
  deviation: "fill-amber-500",
};
/** The drawing's width in its own units: bars narrower than a unit are drawn a unit wide, as the 3 px of old. */
const WIDE = 1000;

const KEYS: Record<string, (i: number, count: number) => number> = {
  ArrowRight: (i, count) => Math.min(count - 1, i + 1),
  ArrowLeft: (i) => Math.max(0, i - 1),
  Home: () => 0,
  End: (_, count) => count - 1,
};

/**
 * A lane's bars as one path per colour, and one button on the chosen bar: the
 * keyboard's way along the lane (arrow keys, Home, End) and to seek (Enter).
 */
function DrawnMarks({
  name,
  marks,
  total,
  onSeek,
}: {
  name: string;
  marks: Mark[];
  total: number;
  onSeek: (ms: number) => void;
}) {
  const [chosen, setChosen] = useState(0);
  const x = (ms: number) => (Math.min(total, Math.max(0, ms)) / total) * WIDE;
  // The drawing changes with the marks and the time axis only; the playhead moves often.
  // biome-ignore lint/correctness/useExhaustiveDependencies: x follows from total, listed
  const paths = useMemo(() => {
    const paths = new Map<string, string[]>();
    for (const m of marks) {
      const d = paths.get(m.tone) ?? [];
      d.push(
        `M${x(m.at).toFixed(2)} 0h${Math.max(2, x(m.to) - x(m.at)).toFixed(2)}v1h-${Math.max(2, x(m.to) - x(m.at)).toFixed(2)}z`,
      );
      paths.set(m.tone, d);
    }
    return paths;
  }, [marks, total]);
  const mark = marks[Math.min(chosen, marks.length - 1)];
  return (
    <>
      <svg
        className="pointer-events-none absolute inset-x-0 top-1 bottom-1 h-4 w-full"
        viewBox={`0 0 ${WIDE} 1`}
        preserveAspectRatio="none"
        aria-hidden
      >
        {[...paths].map(([tone, d]) => (
          <path key={tone} className={FILL[tone as Mark["tone"]]} d={d.join("")} />
        ))}
      </svg>
      {mark && (
        <button
          type="button"
          title={mark.title}
          aria-label={`${mark.label} (${name.toLowerCase()} ${Math.min(chosen, marks.length - 1) + 1} of ${marks.length}; arrow keys choose another)`}
          className="absolute top-0 bottom-0 rounded-sm outline-offset-1 focus-visible:ring-2 focus-visible:ring-brand-600"
          style={{
            left: `${(x(mark.at) / WIDE) * 100}%`,
            width: `max(6px, ${((x(mark.to) - x(mark.at)) / WIDE) * 100}%)`,
          }}
          onClick={() => onSeek(mark.at)}
          onKeyDown={(event) => {
            const move = KEYS[event.key];
            if (!move) return;
            event.preventDefault();
            setChosen(move(Math.min(chosen, marks.length - 1), marks.length));
          }}
        />
      )}
    </>
  );
}
