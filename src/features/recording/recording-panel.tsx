"use client";
// The wizard's recorder: choose the camera and microphone, start, and see at
// a glance that it is recording and that its parts reach the server. A page
// opened again after the last one closed mid-recording says what was kept.
import { Circle, Square, Video } from "lucide-react";
import { useEffect, useRef, useState } from "react";
import { Button } from "@/ui/button";
import { NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";
import { useCutOff } from "./use-cut-off";
import { useRecorder } from "./use-recorder";

const clock = (ms: number) =>
  `${String(Math.floor(ms / 60000)).padStart(2, "0")}:${String(Math.floor(ms / 1000) % 60).padStart(2, "0")}`;

export function RecordingPanel({
  trialId,
  startedAt,
  ended,
  logStart,
  onStream,
}: {
  trialId: string;
  startedAt: string | null;
  ended: boolean;
  logStart: (recordingId: string, offsetMs: number) => void;
  /** The camera and microphone while they are recorded (null otherwise): the live video's source. */
  onStream?: (stream: MediaStream | null) => void;
}) {
  const recorder = useRecorder(trialId, startedAt, ended, logStart);
  useEffect(() => onStream?.(recorder.stream), [onStream, recorder.stream]);
  const [camera, setCamera] = useState("");
  const [microphone, setMicrophone] = useState("");
  const cameras = recorder.devices.filter((d) => d.kind === "videoinput");
  const microphones = recorder.devices.filter((d) => d.kind === "audioinput");
  const active = recorder.state === "recording" || recorder.state === "finishing";
  const cutOff = useCutOff(trialId, !active && recorder.state !== "starting");
  // The wizard sees what their camera records, muted so the room does not echo.
  const selfView = useRef<HTMLVideoElement>(null);
  useEffect(() => {
    if (selfView.current) selfView.current.srcObject = recorder.stream;
  }, [recorder.stream]);
  return (
    <Card className="space-y-3 p-4 text-sm">
      <h2 className="flex items-center gap-2 font-semibold">
        <Video className="h-4 w-4" aria-hidden /> Recording
        {active && (
          <span
            role="status"
            data-testid="recording-indicator"
            className="ml-auto flex items-center gap-1 font-mono text-red-700"
          >
            <Circle className="h-3 w-3 animate-pulse fill-red-600 text-red-600" aria-hidden /> REC{" "}
            {clock(recorder.elapsedMs)}
          </span>
        )}
      </h2>
      {cutOff.words && (
        <p role="status" className="text-amber-900" data-testid="recording-cut-off">
          {cutOff.words}
        </p>
      )}
      {!active && recorder.state !== "saved" && (
        <>
          <NativeSelect aria-label="Camera" value={camera} onChange={(e) => setCamera(e.target.value)}>
            <option value="">Default camera</option>
            {cameras.map((d, i) => (
              <option key={d.deviceId || i} value={d.deviceId}>
                {d.label || `Camera ${i + 1}`}
              </option>
            ))}
          </NativeSelect>
          <NativeSelect aria-label="Microphone" value={microphone} onChange={(e) => setMicrophone(e.target.value)}>
            <option value="">Default microphone</option>
            {microphones.map((d, i) => (
              <option key={d.deviceId || i} value={d.deviceId}>
                {d.label || `Microphone ${i + 1}`}
              </option>
            ))}
          </NativeSelect>
          <Button
            size="sm"
            disabled={recorder.state === "starting" || ended}
            onClick={() => void recorder.start(camera, microphone)}
          >
            <Circle className="h-3.5 w-3.5 fill-current" aria-hidden />{" "}
            {cutOff.words && !ended ? "Record again" : "Start recording"}
          </Button>
        </>
      )}
      {recorder.stream && (
        <video
          ref={selfView}
          data-testid="self-view"
          aria-label="Your camera, as it is recorded"
          autoPlay
          muted
          playsInline
          className="w-32 rounded bg-black"
        />
      )}
      {active && (
        <>
          <p className="text-xs text-slate-600" data-testid="recording-parts">
            {recorder.sent} part{recorder.sent === 1 ? "" : "s"} saved on the server
            {recorder.waiting ? `, ${recorder.waiting} waiting to be sent` : ""}
          </p>
          <Button
            size="sm"
            variant="secondary"
            disabled={recorder.state === "finishing"}
            onClick={() => void recorder.stop()}
          >
            <Square className="h-3.5 w-3.5" aria-hidden />{" "}
            {recorder.state === "finishing" ? "Saving…" : "Stop and save"}
          </Button>
        </>
      )}
      {recorder.state === "saved" && <p className="text-emerald-800">The recording is saved with this trial.</p>}
      {recorder.problem && <Problem error={{ message: recorder.problem }} />}
      {!active && recorder.state === "idle" && (
        <p className="text-xs text-slate-500">It stops and is saved by itself when the trial ends.</p>
      )}
    </Card>
  );
}
