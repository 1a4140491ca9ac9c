import { describe, expect, it } from "vitest";
import { actionProblems, TIMED_OUT } from "./problems";
import type { TrialEvent } from "./types";

const requested = (actionId: string): TrialEvent => ({
  seq: 1,
  relMs: 0,
  type: "action.requested",
  stepId: "s1",
  actionId,
  actionType: "posture",
  parameters: {},
  scripted: true,
});
const failed = (actionId: string, reason: string): TrialEvent => ({
  seq: 2,
  relMs: 1,
  type: "action.failed",
  actionId,
  reason,
});
const timedOut = (actionId: string): TrialEvent => ({ seq: 3, relMs: 2, type: "action.timed_out", actionId });
const completed = (actionId: string): TrialEvent => ({ seq: 4, relMs: 3, type: "action.completed", actionId });
const unknown = (actionId: string, reason: string): TrialEvent => ({
  seq: 5,
  relMs: 4,
  type: "action.unknown",
  actionId,
  reason,
});
const notSent = (actionId: string, reason: string): TrialEvent => ({
  seq: 6,
  relMs: 5,
  type: "action.not_sent",
  actionId,
  reason,
});

describe("why an action was not done, for the wizard", () => {
  it.each<[string, TrialEvent[], Record<string, string>]>([
    ["nothing went wrong", [requested("a"), completed("a")], {}],
    [
      "a failure, in the words it was logged with, as a sentence",
      [requested("a"), failed("a", '"Sit" cannot run on NAO6: it needs SSH to the robot')],
      { a: '"Sit" cannot run on NAO6: it needs SSH to the robot.' },
    ],
    [
      "the robot's own refusal",
      [requested("a"), failed("a", "the robot refused the command (exit 1): motors are off")],
      { a: "The robot refused the command (exit 1): motors are off." },
    ],
    ["a reason that already ends a sentence", [failed("a", "Robot not connected!")], { a: "Robot not connected!" }],
    ["an empty reason", [failed("a", "  ")], { a: "No reason was given." }],
    ["a timeout", [requested("a"), timedOut("a")], { a: TIMED_OUT }],
    ["not sent, with why", [requested("a"), notSent("a", "asked too long ago")], { a: "Asked too long ago." }],
    [
      "sent, outcome unknown, with why",
      [requested("a"), unknown("a", "the link was lost")],
      { a: "The link was lost." },
    ],
    ["an outcome unknown the robot later reported done", [requested("a"), unknown("a", "lost"), completed("a")], {}],
    ["sent again after failing", [requested("a"), failed("a", "x"), requested("a")], {}],
    ["sent again and failed again", [failed("a", "first"), requested("a"), failed("a", "second")], { a: "Second." }],
    [
      "each action its own",
      [failed("a", "one"), timedOut("b"), requested("c"), completed("c")],
      { a: "One.", b: TIMED_OUT },
    ],
  ])("%s", (_, events, expected) => {
    expect(actionProblems(events)).toEqual(expected);
  });
});
