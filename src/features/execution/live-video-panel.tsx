"use client";
// What the live video looks like on the trial page: the watcher's picture
// with how well it arrives, and the wizard's line saying who receives it.
import { Video, Volume2, VolumeX } from "lucide-react";
import { useEffect, useRef, useState } from "react";
import type { Viewer } from "@/core/socket/messages";
import { Button } from "@/ui/button";
import { Card } from "@/ui/surface";
import { useVideoSource, useVideoWatcher, type VideoChannel } from "./use-live-video";

const TONE = { good: "text-emerald-800", fair: "text-amber-800", poor: "text-red-700" } as const;

export function WatchVideo({ video, viewers }: { video: VideoChannel | null; viewers: Viewer[] }) {
  const { stream, quality } = useVideoWatcher(video, viewers);
  const element = useRef<HTMLVideoElement>(null);
  // Browsers play a video with sound only after a click: it starts muted, one click brings the sound.
  const [muted, setMuted] = useState(true);
  useEffect(() => {
    if (element.current) element.current.srcObject = stream;
  }, [stream]);
  return (
    <Card className="space-y-2 p-4 text-sm">
      <h2 className="flex items-center gap-2 font-semibold">
        <Video className="h-4 w-4" aria-hidden /> Live video
        {stream && (
          <Button size="sm" variant="secondary" className="ml-auto" onClick={() => setMuted((m) => !m)}>
            {muted ? <VolumeX className="h-3.5 w-3.5" aria-hidden /> : <Volume2 className="h-3.5 w-3.5" aria-hidden />}
            {muted ? "Sound off" : "Sound on"}
          </Button>
        )}
      </h2>
      <video
        ref={element}
        data-testid="live-video"
        autoPlay
        playsInline
        muted={muted}
        className={stream ? "w-full rounded bg-black" : "hidden"}
      />
      {!stream && (
        <p className="text-slate-600">
          The wizard's camera is not on: the picture appears here once the wizard starts recording.
        </p>
      )}
      {stream && (
        <p data-testid="video-quality" className={quality ? TONE[quality.level] : "text-slate-500"}>
          {quality?.words ?? "Measuring the connection…"}
        </p>
      )}
    </Card>
  );
}

export function SendVideo({
  video,
  viewers,
  stream,
}: {
  video: VideoChannel | null;
  viewers: Viewer[];
  stream: MediaStream | null;
}) {
  const { sending } = useVideoSource(video, viewers, stream);
  return (
    <p className="text-xs text-slate-600" data-testid="video-sending">
      {stream
        ? `Live video: your camera and microphone go to ${sending} watching.`
        : "Live video: those watching see your camera once you start recording."}
    </p>
  );
}
