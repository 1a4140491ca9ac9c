"use client";
// What the simulated robot is doing, drawn from its own state topic over
// rosbridge (the same protocol as a real robot), with its speech spoken by
// the browser's speech synthesis when asked.
import { useEffect, useRef, useState } from "react";
import * as ROSLIB from "roslib";
import { readableValue } from "@/core/designer/action-name";
import { REPLAY_TOPIC, ROBOT_STATE_TOPIC, type ReplayAnnouncement, type RobotState } from "@/core/robots/robot-state";
import { Button } from "@/ui/button";
import { clockTime } from "@/ui/clock-time";
import { Badge, Card } from "@/ui/surface";
import { ReplayBanner } from "./replay-banner";
import { SenseControls } from "./sense-controls";

// A replay announces itself every second while it plays: one unheard for longer has gone (its runtime stopped).
const REPLAY_GONE_MS = 3000;

export function RobotView({ url }: { url: string }) {
  const [state, setState] = useState<RobotState | null>(null);
  const [connected, setConnected] = useState(false);
  // The open connection, for the controls that make the robot sense; null while it is lost.
  const [link, setLink] = useState<ROSLIB.Ros | null>(null);
  const [voice, setVoice] = useState(false);
  const [replay, setReplay] = useState<(ReplayAnnouncement & { heardAt: number }) | null>(null);
  const spoken = useRef<string | null>(null);

  useEffect(() => {
    let stopped = false;
    let ros: ROSLIB.Ros | null = null;
    const open = () => {
      if (stopped) return;
      const opened = new ROSLIB.Ros({});
      ros = opened;
      ros.on("connection", () => {
        setConnected(true);
        setLink(opened);
      });
      const lost = () => {
        setConnected(false);
        setLink(null);
        setTimeout(open, 1000);
      };
      ros.on("close", lost);
      ros.on("error", () => undefined);
      void ros.connect(url).catch(() => undefined);
      const topic = new ROSLIB.Topic({ ros, name: ROBOT_STATE_TOPIC, messageType: "std_msgs/msg/String" });
      topic.subscribe((message) => setState(JSON.parse((message as { data: string }).data) as RobotState));
      const replays = new ROSLIB.Topic({ ros, name: REPLAY_TOPIC, messageType: "std_msgs/msg/String" });
      replays.subscribe((message) =>
        setReplay({ ...(JSON.parse((message as { data: string }).data) as ReplayAnnouncement), heardAt: Date.now() }),
      );
    };
    open();
    return () => {
      stopped = true;
      ros?.close();
    };
  }, [url]);

  // A replay that stopped announcing itself is over, whether or not its end was heard.
  useEffect(() => {
    if (!replay?.playing) return;
    const timer = setTimeout(() => setReplay((r) => r && { ...r, playing: false }), REPLAY_GONE_MS);
    return () => clearTimeout(timer);
  }, [replay]);

  useEffect(() => {
    const text = state?.speaking;
    if (!voice || !text || spoken.current === text || typeof speechSynthesis === "undefined") return;
    spoken.current = text;
    speechSynthesis.speak(new SpeechSynthesisUtterance(text));
  }, [state?.speaking, voice]);

  return (
    <div className="space-y-4">
      <div className="flex items-center gap-3">
        <h1 className="text-2xl font-semibold">Simulated robot</h1>
        <Badge tone={connected ? "green" : "red"}>{connected ? "connected" : "not connected"}</Badge>
        <Button variant="secondary" size="sm" className="ml-auto" aria-pressed={voice} onClick={() => setVoice(!voice)}>
          {voice ? "Mute robot voice" : "Speak through this browser"}
        </Button>
      </div>
      {replay && <ReplayBanner replay={replay} />}
      <Card className="flex flex-col items-center gap-6 p-10">
        <div
          role="status"
          aria-label="Robot speech"
          className="min-h-16 max-w-xl rounded-2xl border border-slate-200 bg-white px-5 py-3 text-center text-lg shadow-sm"
        >
          {state?.speaking ? (
            `“${state.speaking}”`
          ) : state?.playing ? (
            `♪ ${state.playing.name}`
          ) : (
            <span className="text-slate-500">{state?.lastSaid ? `Last said: “${state.lastSaid}”` : "…"}</span>
          )}
        </div>
        <RobotFigure state={state} />
        <SaidLines said={state?.said ?? []} />
        <dl className="grid grid-cols-2 gap-x-8 gap-y-1 text-sm sm:grid-cols-4">
          {/* An animation arrives as the robot's path to it (animations/Stand/Gestures/Hey_1): shown by its name. */}
          <Fact label="Gesture" value={readable(state?.gesture ?? state?.animation) ?? "none"} />
          <Fact
            label="Posture"
            value={state ? `${readable(state.posture) ?? "—"}${state.awake ? "" : " (motors off)"}` : "—"}
          />
          <Fact
            label="Moving"
            value={
              state && (state.velocity.linear || state.velocity.angular)
                ? `${state.velocity.linear} m/s, ${state.velocity.angular} rad/s`
                : "no"
            }
          />
          <Fact label="Battery" value={state ? `${Math.round(state.battery)} %` : "—"} />
        </dl>
        <SenseControls ros={link} />
      </Card>
      <p className="text-sm text-slate-500">
        This page shows the built-in simulated robot that <code className="font-mono">npm start</code> runs when no real
        robot is configured.
      </p>
    </div>
  );
}

/** Every line of the last few, newest first: a line said while nobody looked is still there to read. */
function SaidLines({ said }: { said: Array<{ text: string; at: string }> }) {
  if (!said.length) return null;
  return (
    <section aria-label="Lines said" className="w-full max-w-xl text-sm">
      <h2 className="mb-1 font-semibold">Lines said</h2>
      <ol className="space-y-1">
        {said
          .map((line, i) => (
            <li key={i} className="flex gap-3">
              <time dateTime={line.at} className="shrink-0 tabular-nums text-slate-500">
                {clockTime(line.at)}
              </time>
              <span>{line.text}</span>
            </li>
          ))
          .reverse()}
      </ol>
    </section>
  );
}

const readable = (value: string | null | undefined) => (value ? readableValue(value) : undefined);

function Fact({ label, value }: { label: string; value: string }) {
  return (
    <div>
      <dt className="text-slate-500">{label}</dt>
      <dd className="font-medium" data-testid={`robot-${label.toLowerCase()}`}>
        {value}
      </dd>
    </div>
  );
}

/** A simple NAO-like figure: the head tilts with head pitch, the arm rises with a gesture. */
function RobotFigure({ state }: { state: RobotState | null }) {
  const tilt = ((state?.headPitch ?? 0) * 180) / Math.PI;
  const waving = Boolean(state?.gesture ?? state?.animation);
  // Seated, crouched or at rest, the legs fold (NAOqi's Sit, SitRelax, Crouch; rest is crouched).
  const legs = /^(sit|crouch|rest)/.test(state?.posture ?? "") ? 24 : 44;
  return (
    <svg viewBox="0 0 120 160" className="h-56" aria-hidden>
      <g transform={`rotate(${tilt} 60 40)`}>
        <rect x="35" y="10" width="50" height="40" rx="14" fill="#e2e8f0" stroke="#475569" />
        <circle cx="50" cy="30" r="4" fill={state?.speaking ? "#2458b8" : "#475569"} />
        <circle cx="70" cy="30" r="4" fill={state?.speaking ? "#2458b8" : "#475569"} />
      </g>
      <rect x="38" y="55" width="44" height="50" rx="8" fill="#f8fafc" stroke="#475569" />
      <rect
        x="16"
        y={waving ? 30 : 58}
        width="12"
        height="40"
        rx="6"
        fill="#f8fafc"
        stroke="#475569"
        transform={waving ? "rotate(-30 22 50)" : undefined}
      />
      <rect x="92" y="58" width="12" height="40" rx="6" fill="#f8fafc" stroke="#475569" />
      <rect x="42" y="108" width="14" height={legs} rx="6" fill="#f8fafc" stroke="#475569" />
      <rect x="64" y="108" width="14" height={legs} rx="6" fill="#f8fafc" stroke="#475569" />
    </svg>
  );
}
