"use client";
// The wizard's controls: the next scripted action as the big button, answer
// choices by number, a pending wait's go on, and everything off script one key away.
import { useId, useRef, useState } from "react";
import { actionName, type ActionNames } from "@/core/designer/action-name";
import type { EventNames } from "@/core/plugins/event-names";
import {
  answerOptions,
  exitNow,
  nextUnit,
  pendingWait,
  type StoredEvent,
  type TrialProtocol,
  type TrialState,
} from "@/core/trial";
import type { RuntimeState } from "@/core/trial/connections";
import { controlsOffBecause } from "@/core/trial/refusals";
import type { WizardCommand } from "@/core/socket/messages";
import { Button } from "@/ui/button";
import { Input } from "@/ui/field";
import { isTyping, useKeys } from "@/ui/use-keys";
import { UnscriptedAction } from "./unscripted-action";
import { WaitPanel } from "./wait-panel";

type Send = (c: WizardCommand) => Promise<{ ok: boolean }>;

export const SHORTCUTS = [
  ["N", "start / next action"],
  ["S", "skip the next action"],
  ["1–9", "record answer"],
  ["G", "go on: end a wait for the robot's senses"],
  ["U", "unscripted speech"],
  ["P", "pause / resume"],
  ["Esc", "emergency stop"],
] as const;

export function nextLabel(protocol: TrialProtocol, state: TrialState, names: ActionNames): string {
  if (state.status === "scheduled") return "Start trial";
  const unit = nextUnit(protocol, state);
  if (unit.length) return unit.map((a) => actionName(a, names)).join(" + ");
  // Where this step leads, as the engine will go: answers' steps rejoin, a step may end the trial.
  const exit = exitNow(
    protocol,
    state,
    protocol.steps.findIndex((s) => s.id === state.currentStepId),
  );
  return exit.to === "step" ? `Go to “${protocol.steps[exit.index]!.name}”` : "Finish trial";
}

export function WizardControls({
  protocol,
  names,
  eventNames,
  state,
  runtime,
  send,
  events,
}: {
  protocol: TrialProtocol;
  names: ActionNames;
  /** The plugin's names of what its robot senses: the wait panel says "Head touched", not head_touched. */
  eventNames: EventNames;
  state: TrialState;
  /** The page's link to the trial runtime: unless it is live, nothing can be sent. */
  runtime: RuntimeState;
  send: Send;
  /** The trial's log so far: a pending wait lists the robot's latest observations from it. */
  events: ReadonlyArray<StoredEvent<string>>;
}) {
  const speech = useRef<HTMLInputElement>(null);
  const [text, setText] = useState("");
  const [note, setNote] = useState("");
  const [confirmAbort, setConfirmAbort] = useState(false);
  const unit = nextUnit(protocol, state);
  const question = unit[0]?.type === "record_answer" ? unit[0] : null;
  const options = question ? answerOptions(question) : [];
  const wait = pendingWait(protocol, state);
  const goOn = () => void send({ kind: "go_on" });
  const running = state.status === "in_progress";
  // An ended trial takes no command, emergency stop included, and nothing is sent without the runtime:
  // every control is off, and the page says why.
  const offBecause = controlsOffBecause(state, runtime);
  const off = offBecause !== null;
  const ended = state.status === "completed" || state.status === "aborted";
  const offId = useId();
  const next = () => void send(state.status === "scheduled" ? { kind: "start" } : { kind: "next" });

  useKeys((e) => {
    if (e.key === "Escape") {
      if (!off) void send({ kind: "emergency_stop" });
      return;
    }
    if (isTyping(e.target) || e.ctrlKey || e.metaKey || e.altKey || off) return;
    const key = e.key.toLowerCase();
    if (key === "g" && wait) goOn();
    else if (key === "n" && !question && !wait) next();
    else if (key === "s" && running) void send({ kind: "skip" });
    else if (key === "p") void send({ kind: state.status === "paused" ? "resume" : "pause" });
    else if (key === "u") {
      e.preventDefault();
      speech.current?.focus();
    } else if (/^[1-9]$/.test(key) && question) {
      const option = options[Number(key) - 1];
      if (option) void send({ kind: "answer", actionId: question.id, optionId: option.id });
    }
  });

  const say = async () => {
    if (!text.trim()) return;
    const done = await send({ kind: "unscripted", actionType: "say", parameters: { text } });
    if (done.ok) setText("");
  };

  const addNote = async () => {
    if (!note.trim()) return;
    if ((await send({ kind: "note", text: note })).ok) setNote("");
  };

  return (
    <div className="space-y-4">
      {offBecause && (
        <p
          id={offId}
          role="status"
          className="rounded-md border border-slate-300 bg-slate-50 p-3 text-sm text-slate-700"
        >
          {offBecause}
        </p>
      )}
      <fieldset disabled={off} aria-describedby={off ? offId : undefined} className="min-w-0 space-y-4">
        <legend className="sr-only">Wizard controls</legend>
        {wait ? (
          <WaitPanel
            protocol={protocol}
            stepIndex={protocol.steps.findIndex((s) => s.id === state.currentStepId)}
            wait={wait}
            events={events}
            names={eventNames}
            goOn={goOn}
          />
        ) : question ? (
          <div className="rounded-lg border-2 border-brand-500 bg-brand-50 p-4">
            <p className="font-medium">{String(question.parameters.prompt ?? "Record the participant's answer")}</p>
            <div className="mt-3 flex flex-wrap gap-2">
              {options.map((o, i) => (
                <Button
                  key={o.id}
                  size="lg"
                  onClick={() => void send({ kind: "answer", actionId: question.id, optionId: o.id })}
                >
                  <kbd className="rounded bg-white/20 px-1.5 text-xs">{i + 1}</kbd> {o.label}
                </Button>
              ))}
            </div>
          </div>
        ) : (
          <Button size="lg" className="h-16 w-full text-lg" disabled={off || state.status === "paused"} onClick={next}>
            <kbd className="rounded bg-white/20 px-1.5 text-xs">N</kbd>{" "}
            {ended ? "Trial ended" : nextLabel(protocol, state, names)}
          </Button>
        )}
        <div className="flex flex-wrap gap-2">
          <Button
            variant="secondary"
            disabled={!running || unit.length === 0}
            onClick={() => void send({ kind: "skip" })}
          >
            Skip (S)
          </Button>
          <Button
            variant="secondary"
            disabled={ended || state.status === "scheduled"}
            onClick={() => void send({ kind: state.status === "paused" ? "resume" : "pause" })}
          >
            {state.status === "paused" ? "Resume (P)" : "Pause (P)"}
          </Button>
          <Button
            variant="secondary"
            disabled={ended || state.status === "scheduled"}
            onClick={() => void send({ kind: "complete" })}
          >
            Complete trial
          </Button>
          {/* Disarmed once the trial has ended: no longer red, and Esc does nothing. */}
          <Button
            variant={ended ? "secondary" : "danger"}
            disabled={ended || state.status === "scheduled"}
            onClick={() => void send({ kind: "emergency_stop" })}
          >
            Emergency stop (Esc)
          </Button>
          {confirmAbort && !ended ? (
            <Button
              variant="danger"
              onClick={() =>
                void send({ kind: "abort", reason: "Aborted by the wizard" }).then(() => setConfirmAbort(false))
              }
            >
              Confirm: abort this trial
            </Button>
          ) : (
            <Button variant="ghost" disabled={ended} onClick={() => setConfirmAbort(true)}>
              Abort trial…
            </Button>
          )}
        </div>
        <form
          className="flex gap-2"
          onSubmit={(e) => {
            e.preventDefault();
            void say();
          }}
        >
          <Input
            ref={speech}
            aria-label="Unscripted speech"
            placeholder="Say something off script (U)…"
            value={text}
            onChange={(e) => setText(e.target.value)}
            disabled={!running}
          />
          <Button type="submit" variant="secondary" disabled={!running}>
            Say
          </Button>
        </form>
        <UnscriptedAction send={send} disabled={!running} />
        <form
          className="flex gap-2"
          onSubmit={(e) => {
            e.preventDefault();
            void addNote();
          }}
        >
          <Input
            aria-label="Wizard note"
            placeholder="Note for the log (not said by the robot)…"
            value={note}
            onChange={(e) => setNote(e.target.value)}
            disabled={ended}
          />
          <Button type="submit" variant="ghost" disabled={ended}>
            Add note
          </Button>
        </form>
      </fieldset>
    </div>
  );
}
