"use client";
// Replay on the simulated robot: the trial's robot commands sent again with
// their timing, from the playhead, at ×1 or ×2. With a recording, the replay
// follows it: playing the video starts the robot at the video's moment, and
// pausing or seeking the video stops or moves the robot with it. R toggles it.
import { type RefObject, useEffect, useRef, useState } from "react";
import { Button } from "@/ui/button";
import { seconds } from "@/ui/format";
import { Card } from "@/ui/surface";
import { isTyping, useKeys } from "@/ui/use-keys";
import { followVideo, type VideoEvent } from "@/core/analysis/replay-follow";
import { type Recording, trialMs } from "./recording-player";
import { useReplay } from "./use-replay";

// The speeds offered here; a video slowed to ×0.5 is followed too (REPLAY_SPEEDS).
const SPEEDS = [1, 2] as const;

export function ReplayControl({
  trialId,
  playheadMs,
  recording,
  video,
}: {
  trialId: string;
  playheadMs: number | null;
  recording: Recording | null;
  video: RefObject<HTMLVideoElement | null>;
}) {
  const replay = useReplay(trialId);
  const [speed, setSpeed] = useState<number>(1);
  // On: the robot replays (and, with a recording, follows the video until turned off).
  const [on, setOn] = useState(false);
  // Why the robot stopped following the video, when the video did something a replay cannot.
  const [notice, setNotice] = useState<string | null>(null);
  const playing = replay.status?.playing ?? false;
  const latest = useRef({ replay, speed, startedAt: 0 });
  latest.current = { ...latest.current, replay, speed };

  // Following the recording: the video's play, pause, seek and rate move the robot with it (followVideo).
  useEffect(() => {
    const v = video.current;
    if (!on || !recording || !v) return;
    const follow = (event: Event) => {
      // The play (and speed) that Replay itself set: the robot has already started there.
      if (event.type !== "pause" && event.type !== "seeked" && performance.now() - latest.current.startedAt < 500)
        return;
      const at = { paused: v.paused, atMs: trialMs(recording, v.currentTime), rate: v.playbackRate };
      const move = followVideo(event.type as VideoEvent, at);
      setNotice(move.kind === "stop" ? (move.reason ?? null) : null);
      if (move.kind === "play") void latest.current.replay.play(move.fromMs, move.speed);
      else if (move.kind === "stop") void latest.current.replay.stop();
    };
    const events: VideoEvent[] = ["play", "pause", "seeked", "ratechange"];
    for (const e of events) v.addEventListener(e, follow);
    return () => {
      for (const e of events) v.removeEventListener(e, follow);
    };
  }, [on, recording, video]);

  const start = () => {
    setOn(true);
    setNotice(null);
    const v = video.current;
    if (!recording || !v) return void replay.play(playheadMs ?? 0, speed);
    // The video is the clock: the robot starts at its moment (the playhead follows it), and plays with it.
    latest.current.startedAt = performance.now();
    v.playbackRate = speed;
    void replay.play(trialMs(recording, v.currentTime), speed);
    if (v.paused) void v.play().catch(() => undefined);
  };
  const stop = () => {
    setOn(false);
    void replay.stop();
  };
  const toggle = () => (on && playing ? stop() : start());
  useKeys((e) => {
    if (isTyping(e.target) || e.ctrlKey || e.metaKey || e.altKey || e.key.toLowerCase() !== "r") return;
    toggle();
  });

  const chooseSpeed = (s: number) => {
    setSpeed(s);
    // With a recording the video changes speed, and the robot follows it; without, the replay
    // goes on at the new speed just after the last command it sent (not sending that one again).
    if (video.current && recording) video.current.playbackRate = s;
    else if (playing) void replay.play(replay.status!.positionMs + 1, s);
  };

  const status = replay.status;
  return (
    <section aria-label="Replay on the simulated robot">
      <Card className="flex flex-wrap items-center gap-3 p-4">
        <h2 className="text-sm font-semibold">Replay on the simulated robot</h2>
        <fieldset aria-label="Replay speed" className="flex gap-1">
          {SPEEDS.map((s) => (
            <Button
              key={s}
              size="sm"
              variant={speed === s ? "primary" : "secondary"}
              aria-pressed={speed === s}
              onClick={() => chooseSpeed(s)}
            >
              ×{s}
            </Button>
          ))}
        </fieldset>
        {on && playing ? (
          <Button size="sm" variant="secondary" aria-keyshortcuts="R" onClick={stop}>
            Stop replay
          </Button>
        ) : (
          <Button size="sm" aria-keyshortcuts="R" onClick={start}>
            Replay from {seconds(playheadMs ?? 0)}
          </Button>
        )}
        <p className="text-sm text-slate-600" role="status">
          {status?.playing
            ? `Replaying from ${seconds(status.fromMs)} at ×${status.speed}: ${status.sent} of ${status.total} robot commands sent${recording ? ", following the recording" : ""}.`
            : (status?.detail ??
              `Sends this trial's robot commands again, with their timing, to the simulated robot (never a real one)${recording ? "; with the recording playing, the robot follows it" : ""}. Press R.`)}
        </p>
        {(replay.problem ?? notice) && (
          <p role="alert" className="w-full text-sm text-red-700">
            {replay.problem ?? notice}
          </p>
        )}
        {status && status.skipped.length > 0 && (
          <p className="w-full text-xs text-slate-500">Not replayed: {[...new Set(status.skipped)].join("; ")}.</p>
        )}
      </Card>
    </section>
  );
}
