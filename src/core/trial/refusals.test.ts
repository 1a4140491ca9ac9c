import { describe, expect, it } from "vitest";
import { fold } from "./fold";
import type { RuntimeState } from "./connections";
import { controlsOffBecause, type Refusal, refusalInForce } from "./refusals";
import type { EngineEvent, TrialProtocol, TrialState } from "./types";

const protocol: TrialProtocol = {
  steps: [
    { id: "s1", name: "Intro", actions: [{ id: "p", type: "pause", parameters: { seconds: 3 } }] },
    { id: "s2", name: "Goodbye", actions: [{ id: "bye", type: "say", parameters: { text: "Bye" } }] },
  ],
};

/** The state after these events, numbered from 1 as the log numbers them. */
const stateAfter = (...bodies: EngineEvent[]): TrialState =>
  fold(
    protocol,
    bodies.map((e, i) => ({ ...e, seq: i + 1, relMs: i })),
  );

const started: EngineEvent[] = [
  { type: "trial.started" },
  { type: "step.entered", stepId: "s1", via: "start" },
  {
    type: "action.requested",
    stepId: "s1",
    actionId: "p",
    actionType: "pause",
    parameters: { seconds: 3 },
    scripted: true,
  },
];
const pauseRefused: Refusal = { reason: "Wait: the 3 s pause is still running.", command: { kind: "next" }, atSeq: 3 };
const notYours: Refusal = {
  reason: "This trial is assigned to another wizard: you may watch it but not run it.",
  command: { kind: "next" },
  atSeq: 3,
};

describe("a refusal lasts as long as its cause", () => {
  it.each<[string, Refusal | null, TrialState, boolean]>([
    ["the pause still runs", pauseRefused, stateAfter(...started), true],
    [
      "the pause still runs, the robot side having reported on it",
      pauseRefused,
      stateAfter(...started, { type: "action.dispatched", actionId: "p" }),
      true,
    ],
    ["the pause has ended", pauseRefused, stateAfter(...started, { type: "action.completed", actionId: "p" }), false],
    [
      "a later step",
      pauseRefused,
      stateAfter(
        ...started,
        { type: "action.completed", actionId: "p" },
        { type: "step.entered", stepId: "s2", via: "next" },
      ),
      false,
    ],
    ["the trial was aborted", pauseRefused, stateAfter(...started, { type: "trial.aborted", reason: "x" }), false],
    ["an emergency stop", pauseRefused, stateAfter(...started, { type: "trial.emergency_stop" }), false],
    ["a refusal not the engine's, nothing happened since", notYours, stateAfter(...started), true],
    [
      "a refusal not the engine's, after something happened",
      notYours,
      stateAfter(...started, { type: "action.dispatched", actionId: "p" }),
      false,
    ],
    [
      "a refused note, nothing happened since",
      { reason: "The note is empty.", command: null, atSeq: 3 },
      stateAfter(...started),
      true,
    ],
    [
      "a refusal whose command the page does not know, after something happened",
      { reason: "The note is empty.", command: null, atSeq: 3 },
      stateAfter(...started, { type: "action.dispatched", actionId: "p" }),
      false,
    ],
    [
      "a paused trial, still paused",
      { reason: "The trial is paused: resume it first.", command: { kind: "next" }, atSeq: 4 },
      stateAfter(...started, { type: "trial.paused" }, { type: "action.completed", actionId: "p" }),
      true,
    ],
    ["no refusal", null, stateAfter(...started), false],
  ])("%s", (_name, refusal, state, shown) => {
    expect(refusalInForce(refusal, protocol, state)).toEqual(shown ? refusal : null);
  });
});

describe("an ended trial's controls", () => {
  it.each<[string, TrialState, RegExp | null]>([
    ["scheduled", stateAfter(), null],
    ["running", stateAfter(...started), null],
    ["paused", stateAfter(...started, { type: "trial.paused" }), null],
    ["emergency-stopped, still live", stateAfter(...started, { type: "trial.emergency_stop" }), null],
    [
      "completed",
      stateAfter(...started, { type: "trial.completed" }),
      /^This trial is completed: nothing more can be sent/,
    ],
    [
      "aborted after an emergency stop",
      stateAfter(...started, { type: "trial.emergency_stop" }, { type: "trial.aborted", reason: "x" }),
      /^This trial was aborted: nothing more can be sent to it or to its robot/,
    ],
  ])("%s", (_name, state, reason) => {
    const off = controlsOffBecause(state);
    if (reason === null) expect(off).toBeNull();
    else expect(off).toMatch(reason);
  });

  it.each<[string, TrialState, RuntimeState, RegExp]>([
    [
      "a running trial",
      stateAfter(...started),
      "reconnecting",
      /^The trial runtime is not connected: nothing can be sent/,
    ],
    [
      "a running trial, the runtime connected but frozen",
      stateAfter(...started),
      "silent",
      /^The trial runtime is not answering: nothing can be sent .* until it answers again/,
    ],
    [
      "a completed one says so first",
      stateAfter(...started, { type: "trial.completed" }),
      "silent",
      /^This trial is completed/,
    ],
  ])("with the runtime away: %s", (_name, state, runtime, reason) => {
    expect(controlsOffBecause(state, runtime)).toMatch(reason);
  });
});
