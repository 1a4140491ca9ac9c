"use client";
// The trial's recording above its timeline: the player reports where it is
// on the trial's clock, and the timeline seeks it. The recording's measured
// offset from t0 converts between the two. A recording cut off by a closed
// page and recorded again comes in parts: they play one after the other, and
// what is between them is said, with why.
import { useQuery } from "@tanstack/react-query";
import { useRef, useState } from "react";
import { inOrder, partAt, type RecordingGap, type RecordingPart } from "@/core/media/recording-parts";
import { useTRPC } from "@/lib/trpc";
import { seconds } from "@/ui/format";
import { Card } from "@/ui/surface";

export type Recording = RecordingPart;

/** While a recording is still open (its page may have gone: the server finishes it soon), the list is asked again. */
const OPEN_EVERY_MS = 5000;

/** The trial's recording: its finished video parts in order, and the one the player holds. */
export function useTrialRecording(trialId: string, enabled: boolean) {
  const trpc = useTRPC();
  const list = useQuery({
    ...trpc.recordings.list.queryOptions({ trialId }),
    enabled,
    refetchInterval: (query) => (query.state.data?.some((r) => r.status === "recording") ? OPEN_EVERY_MS : false),
  });
  const parts = inOrder((list.data ?? []).filter((r) => r.status === "complete" && r.kind === "video"));
  const [index, setIndex] = useState(0);
  const video = useRef<HTMLVideoElement>(null);
  // Where to go in a part once it has loaded, when a seek chose another part (and whether to play on).
  const pending = useRef<{ seconds: number; play: boolean } | null>(null);
  const current = parts[Math.min(index, parts.length - 1)] ?? null;
  /** Shows the trial's moment `ms`: in the part recorded then (or, in a gap, the next one). */
  const seek = (ms: number) => {
    const at = partAt(parts, ms);
    if (!at) return;
    if (parts[at.index] === current && video.current) video.current.currentTime = at.seconds;
    else {
      pending.current = { seconds: at.seconds, play: false };
      setIndex(at.index);
    }
  };
  return { parts, current, index: parts.indexOf(current!), choose: setIndex, seek, video, pending };
}

/** The trial's time (ms from t0) at a point of the recording. */
export const trialMs = (recording: Recording, seconds: number) => seconds * 1000 + (recording.offsetMs ?? 0);

const clock = (ms: number) => seconds(Math.max(0, ms));

export function RecordingPlayer({
  recording,
  gaps,
  onTime,
}: {
  recording: ReturnType<typeof useTrialRecording>;
  gaps: RecordingGap[];
  onTime: (trialMs: number) => void;
}) {
  const { parts, current, index, choose, video, pending } = recording;
  if (!current) return null;
  const report = (v: HTMLVideoElement) => onTime(trialMs(current, v.currentTime));
  return (
    <Card className="overflow-hidden">
      {/* biome-ignore lint/a11y/useMediaCaption: a trial's own recording; no captions exist for it */}
      <video
        ref={video}
        data-testid="trial-video"
        className="max-h-[28rem] w-full bg-black"
        controls
        preload="metadata"
        src={`/api/recordings/${current.id}/media`}
        onLoadedMetadata={(e) => {
          if (pending.current === null) return;
          e.currentTarget.currentTime = pending.current.seconds;
          if (pending.current.play) void e.currentTarget.play().catch(() => undefined);
          pending.current = null;
        }}
        onTimeUpdate={(e) => report(e.currentTarget)}
        onSeeked={(e) => report(e.currentTarget)}
        // The next part follows on.
        onEnded={() => {
          if (index + 1 >= parts.length) return;
          pending.current = { seconds: 0, play: true };
          choose(index + 1);
        }}
      />
      <div className="space-y-1 px-4 py-2 text-xs text-slate-600">
        {parts.length > 1 && (
          <p className="flex flex-wrap items-center gap-2">
            The recording is in {parts.length} parts:
            {parts.map((p, i) => (
              <button
                key={p.id}
                type="button"
                aria-pressed={i === index}
                className="rounded border border-slate-300 px-1.5 py-0.5 font-medium text-slate-800 aria-pressed:bg-slate-800 aria-pressed:text-white"
                onClick={() => choose(i)}
              >
                Part {i + 1} (from {clock(p.offsetMs ?? 0)})
              </button>
            ))}
          </p>
        )}
        {gaps.map((gap) => (
          <p key={gap.fromMs} className="text-amber-900" data-testid="recording-gap">
            Not recorded from {clock(gap.fromMs)} to {clock(gap.toMs)}: {gap.cause}.
          </p>
        ))}
        <p className="text-slate-500">
          Click any moment of the timeline below to see it. {parts.length > 1 ? `Part ${index + 1}` : "The recording"}{" "}
          started {Math.abs((current.offsetMs ?? 0) / 1000).toFixed(1)} s{" "}
          {(current.offsetMs ?? 0) <= 0 ? "before" : "after"} the trial.{" "}
          <a
            className="font-medium text-brand-600 hover:underline"
            href={`/api/recordings/${current.id}/media?download`}
          >
            Download {parts.length > 1 ? "this part" : "the recording"}
          </a>{" "}
          (save it beside the ELAN file to open both together).
        </p>
      </div>
    </Card>
  );
}
