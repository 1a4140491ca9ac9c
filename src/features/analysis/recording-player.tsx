"use client";
// The trial's recording above its timeline: the player reports where it is
// on the trial's clock, and the timeline seeks it. The recording's measured
// offset from t0 converts between the two.
import { useQuery } from "@tanstack/react-query";
import type { RefObject } from "react";
import { useTRPC } from "@/lib/trpc";
import { Card } from "@/ui/surface";

export interface Recording {
  id: string;
  offsetMs: number | null;
}

export function useTrialRecording(trialId: string, enabled: boolean): Recording | null {
  const trpc = useTRPC();
  const list = useQuery({ ...trpc.recordings.list.queryOptions({ trialId }), enabled });
  return list.data?.find((r) => r.status === "complete" && r.kind === "video") ?? null;
}

/** The trial's time (ms from t0) at a point of the recording, and back. */
export const trialMs = (recording: Recording, seconds: number) => seconds * 1000 + (recording.offsetMs ?? 0);
export const videoSeconds = (recording: Recording, ms: number) => Math.max(0, (ms - (recording.offsetMs ?? 0)) / 1000);

export function RecordingPlayer({
  recording,
  video,
  onTime,
}: {
  recording: Recording;
  video: RefObject<HTMLVideoElement | null>;
  onTime: (trialMs: number) => void;
}) {
  return (
    <Card className="overflow-hidden">
      {/* biome-ignore lint/a11y/useMediaCaption: a trial's own recording; no captions exist for it */}
      <video
        ref={video}
        data-testid="trial-video"
        className="max-h-[28rem] w-full bg-black"
        controls
        preload="metadata"
        src={`/api/recordings/${recording.id}/media`}
        onTimeUpdate={(e) => onTime(trialMs(recording, e.currentTarget.currentTime))}
        onSeeked={(e) => onTime(trialMs(recording, e.currentTarget.currentTime))}
      />
      <p className="px-4 py-2 text-xs text-slate-500">
        Click any moment of the timeline below to see it. The recording started{" "}
        {Math.abs((recording.offsetMs ?? 0) / 1000).toFixed(1)} s {(recording.offsetMs ?? 0) <= 0 ? "before" : "after"}{" "}
        the trial.{" "}
        <a
          className="font-medium text-brand-600 hover:underline"
          href={`/api/recordings/${recording.id}/media?download`}
        >
          Download the recording
        </a>{" "}
        (save it beside the ELAN file to open both together).
      </p>
    </Card>
  );
}
