"use client";
// Recording in the wizard's browser: camera and microphone through
// MediaRecorder, a part every few seconds sent to the server as it is made.
// A part that cannot be sent waits and is sent again (the connection came
// back), so a crashed tab or a dropped network loses seconds, not the session.
import { useCallback, useEffect, useRef, useState } from "react";
import { useTRPCClient } from "@/lib/trpc";

const PART_EVERY_MS = 3000;
const RETRY_MS = { first: 500, max: 8000 };

export type RecorderState = "idle" | "starting" | "recording" | "finishing" | "saved" | "failed";

function pickType(): string {
  const wanted = ["video/webm;codecs=vp8,opus", "video/webm;codecs=vp9,opus", "video/webm", "video/mp4"];
  return wanted.find((t) => typeof MediaRecorder !== "undefined" && MediaRecorder.isTypeSupported(t)) ?? "video/webm";
}

/** `logStart` writes the recording's start into the trial's own log (the socket's "recording" command). */
export function useRecorder(
  trialId: string,
  trialStartedAt: string | null,
  trialEnded: boolean,
  logStart: (recordingId: string, offsetMs: number) => void,
) {
  const client = useTRPCClient();
  const [state, setState] = useState<RecorderState>("idle");
  const [problem, setProblem] = useState<string | null>(null);
  const [sent, setSent] = useState(0);
  const [waiting, setWaiting] = useState(0);
  const [elapsedMs, setElapsedMs] = useState(0);
  const [devices, setDevices] = useState<MediaDeviceInfo[]>([]);
  // The camera and microphone being recorded: the trial page streams the same ones to those watching.
  const [stream, setStream] = useState<MediaStream | null>(null);
  const recording = useRef<{
    id: string;
    recorder: MediaRecorder;
    stream: MediaStream;
    startedAt: number;
    type: string;
    next: number;
    offsetSent: boolean;
  } | null>(null);
  const queue = useRef<Array<{ index: number; blob: Blob }>>([]);
  const pumping = useRef<Promise<void> | null>(null);

  const listDevices = useCallback(
    async () => setDevices((await navigator.mediaDevices.enumerateDevices()).filter((d) => d.kind !== "audiooutput")),
    [],
  );
  useEffect(() => void listDevices().catch(() => {}), [listDevices]);

  /** Sends waiting parts in order; a failure waits and tries again, never drops a part. */
  const pump = useCallback(() => {
    pumping.current ??= (async () => {
      let delay = RETRY_MS.first;
      while (queue.current.length && recording.current) {
        const { index, blob } = queue.current[0]!;
        const response = await fetch(`/api/recordings/${recording.current.id}/chunks/${index}`, {
          method: "PUT",
          headers: { "content-type": recording.current.type },
          body: blob,
        }).catch(() => null);
        if (response?.ok) {
          queue.current.shift();
          setSent((n) => n + 1);
          setWaiting(queue.current.length);
          delay = RETRY_MS.first;
        } else if (response?.status === 409) {
          // Finished by the server meanwhile: it heard nothing from this page for too long and kept what it had.
          const gone = recording.current;
          recording.current = null;
          queue.current = [];
          setWaiting(0);
          gone.recorder.ondataavailable = null;
          if (gone.recorder.state !== "inactive") gone.recorder.stop();
          gone.stream.getTracks().forEach((t) => t.stop());
          setStream(null);
          setProblem(
            "The server finished this recording while this page could not reach it; what reached it is kept. Record again to go on.",
          );
          setState("failed");
          return;
        } else if (response && response.status < 500 && response.status !== 408 && response.status !== 429) {
          setProblem(`A part of the recording was refused: ${await response.text()}`);
          setState("failed");
          return;
        } else {
          setProblem(
            "The connection to the server is interrupted: the recording continues and its parts are sent when it is back.",
          );
          await new Promise((r) => setTimeout(r, delay));
          delay = Math.min(RETRY_MS.max, delay * 2);
        }
      }
      setProblem(null);
    })().finally(() => {
      pumping.current = null;
    });
    return pumping.current;
  }, []);

  const start = useCallback(
    async (videoDeviceId: string, audioDeviceId: string) => {
      setProblem(null);
      setState("starting");
      try {
        const stream = await navigator.mediaDevices.getUserMedia({
          video: videoDeviceId ? { deviceId: { exact: videoDeviceId } } : true,
          audio: audioDeviceId ? { deviceId: { exact: audioDeviceId } } : true,
        });
        void listDevices();
        const type = pickType();
        const { recordingId } = await client.recordings.start.mutate({ trialId, kind: "video", mimeType: type });
        const recorder = new MediaRecorder(stream, { mimeType: type });
        recording.current = {
          id: recordingId,
          recorder,
          stream,
          startedAt: Date.now(),
          type,
          next: 0,
          offsetSent: false,
        };
        recorder.ondataavailable = (e) => {
          if (!e.data.size || !recording.current) return;
          queue.current.push({ index: recording.current.next++, blob: e.data });
          setWaiting(queue.current.length);
          void pump();
        };
        recorder.onstart = () => {
          recording.current!.startedAt = Date.now();
          setState("recording");
          setStream(stream);
        };
        recorder.start(PART_EVERY_MS);
      } catch (error) {
        setState("failed");
        setProblem(`The camera or microphone could not be started: ${(error as Error).message}`);
      }
    },
    [client, trialId, pump, listDevices],
  );

  const stop = useCallback(async () => {
    const r = recording.current;
    if (!r || r.recorder.state === "inactive") return;
    setState("finishing");
    const last = new Promise((resolve) => (r.recorder.onstop = resolve));
    r.recorder.stop();
    await last;
    r.stream.getTracks().forEach((t) => t.stop());
    setStream(null);
    while (queue.current.length) await pump();
    try {
      await client.recordings.finish.mutate({ recordingId: r.id, durationMs: Date.now() - r.startedAt });
      setState("saved");
    } catch (error) {
      setState("failed");
      setProblem(`The recording could not be finished: ${(error as Error).message}`);
    }
  }, [client, pump]);

  // The measured offset between the recording's start and the trial's t0, once both are known.
  useEffect(() => {
    const r = recording.current;
    if (!r || r.offsetSent || !trialStartedAt || state !== "recording") return;
    r.offsetSent = true;
    const offsetMs = r.startedAt - new Date(trialStartedAt).getTime();
    void client.recordings.setOffset.mutate({ recordingId: r.id, offsetMs });
    logStart(r.id, offsetMs);
  }, [client, trialStartedAt, state, logStart]);

  // The trial's end finishes the recording.
  useEffect(() => {
    if (trialEnded && state === "recording") void stop();
  }, [trialEnded, state, stop]);

  useEffect(() => {
    if (state !== "recording") return;
    const timer = setInterval(() => setElapsedMs(Date.now() - (recording.current?.startedAt ?? Date.now())), 500);
    return () => clearInterval(timer);
  }, [state]);

  return { state, problem, sent, waiting, elapsedMs, devices, stream, start, stop };
}
