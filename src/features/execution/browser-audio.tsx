"use client";
// Plays, in the wizard's browser, each sound the robot cannot play, and tells
// the runtime when it has ended (or why it could not play), which ends the
// action. A browser that refuses to play without a click gets a button. The
// emergency stop and the trial's end silence it.
import { Volume2 } from "lucide-react";
import { useEffect, useRef, useState } from "react";
import type { WizardCommand } from "@/core/socket/messages";
import type { TrialState } from "@/core/trial";
import { audioUrl } from "@/lib/audio-upload";
import { Button } from "@/ui/button";
import { type BrowserSound, browserSounds } from "./browser-sounds";

type Send = (command: WizardCommand) => unknown;

export function BrowserAudio({
  events,
  state,
  send,
}: {
  events: Parameters<typeof browserSounds>[0];
  state: TrialState;
  send: Send;
}) {
  const sounds = browserSounds(events, state);
  const ended = state.status === "completed" || state.status === "aborted";
  if (!sounds.length) return null;
  return (
    <div className="space-y-2">
      {sounds.map((sound) => (
        <Sound
          key={sound.actionId}
          sound={sound}
          stopped={sound.silenced ? "emergency" : ended ? "ended" : null}
          send={send}
        />
      ))}
    </div>
  );
}

function Sound({ sound, stopped, send }: { sound: BrowserSound; stopped: "emergency" | "ended" | null; send: Send }) {
  const player = useRef<HTMLAudioElement | null>(null);
  const [blocked, setBlocked] = useState(false);
  // One report per sound, whatever the element does after.
  const reported = useRef(false);
  const report = (failed?: string) => {
    if (reported.current) return;
    reported.current = true;
    send({ kind: "played", actionId: sound.actionId, ...(failed ? { failed } : {}) });
  };
  const play = () =>
    player.current?.play().then(
      () => setBlocked(false),
      // Autoplay refused until the wizard clicks: a button, not a failure.
      (error: Error) => (error.name === "NotAllowedError" ? setBlocked(true) : report(error.message)),
    );
  // biome-ignore lint/correctness/useExhaustiveDependencies: started once per sound
  useEffect(() => void play(), []);
  // Silenced by the emergency stop (the log says so, rather than leaving the action running) or by the trial's end.
  // biome-ignore lint/correctness/useExhaustiveDependencies: report sends once per sound, whenever it is called
  useEffect(() => {
    if (!stopped) return;
    player.current?.pause();
    if (stopped === "emergency") report("the emergency stop silenced it");
  }, [stopped]);
  return (
    <div
      role="status"
      className="flex flex-wrap items-center gap-2 rounded-md border border-brand-200 bg-brand-50 px-3 py-2 text-sm"
      data-testid="browser-sound"
    >
      <Volume2 className="h-4 w-4 text-brand-700" aria-hidden />
      <span>
        {blocked ? "Ready to play" : stopped ? "Stopped" : "Playing in this browser"}: <strong>{sound.name}</strong>
      </span>
      {blocked && (
        <Button size="sm" onClick={() => void play()}>
          Play the sound
        </Button>
      )}
      {/* biome-ignore lint/a11y/useMediaCaption: the study's own sound, played for the participant; it has no caption track */}
      <audio
        ref={player}
        src={audioUrl(sound.fileId)}
        preload="auto"
        onEnded={() => report()}
        onError={() => report(`the file “${sound.name}” could not be loaded or decoded`)}
      />
    </div>
  );
}
