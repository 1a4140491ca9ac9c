"use client";
// The trial at a glance, on one time axis under the video: step bands, action
// bars from requested to finished, deviations and annotations. Clicking
// anything seeks the recording there; the playhead shows where it is.
import type { FidelityReport } from "@/core/analysis/fidelity";
import { cn } from "@/ui/cn";
import { seconds } from "@/ui/format";
import { Card } from "@/ui/surface";

interface Props {
  report: FidelityReport;
  deviations: Array<{ at: number; kind: string }>;
  annotations: Array<{ at: number; label: string }>;
  endMs: number;
  playheadMs: number | null;
  onSeek: ((ms: number) => void) | null;
}

const BAND = ["bg-sky-100 text-sky-900", "bg-indigo-100 text-indigo-900"];

export function TimelineChart({ report, deviations, annotations, endMs, playheadMs, onSeek }: Props) {
  const total = Math.max(1, endMs);
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
      {lane(
        "Actions",
        report.actions
          .filter((a) => a.requestedMs !== null)
          .map((a) => (
            <button
              key={a.actionId}
              type="button"
              title={`${a.name}: ${a.outcome}`}
              aria-label={`Action ${a.name} at ${seconds(a.requestedMs)}`}
              className={cn(
                item,
                a.outcome === "executed" ? "bg-emerald-300" : a.outcome === "skipped" ? "bg-amber-300" : "bg-red-300",
              )}
              style={{ left: left(a.requestedMs!), width: width(a.requestedMs!, a.requestedMs! + (a.durationMs ?? 0)) }}
              onClick={() => seek(a.requestedMs!)}
            />
          )),
      )}
      {lane(
        "Deviations",
        deviations.map((d, i) => (
          <button
            key={i}
            type="button"
            title={d.kind.replace("_", " ")}
            aria-label={`Deviation: ${d.kind.replace("_", " ")}`}
            className="absolute top-0 bottom-0 w-1 rounded bg-amber-500"
            style={{ left: left(d.at) }}
            onClick={() => seek(d.at)}
          />
        )),
      )}
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
