import { describe, expect, it } from "vitest";
import { NOT_BLINDED } from "../studies/blinding";
import {
  annotateVerdict,
  cameraVerdict,
  codeVerdict,
  commandVerdict,
  mayReadTrialLog,
  replayVerdict,
  signalVerdict,
  touches,
  type TrialAccess,
} from "./trial-socket";

const me = "u-me";
const access = (
  over: Partial<TrialAccess> & { wizardId?: string | null; status?: TrialAccess["trial"]["status"] } = {},
): TrialAccess => {
  const { wizardId = me, status = "in_progress", ...rest } = over;
  return {
    userId: me,
    name: "Me",
    systemRole: "researcher",
    active: true,
    studyId: "s1",
    studyRole: "wizard",
    studyStatus: "active",
    blinding: NOT_BLINDED,
    trial: { wizardId, status, isRehearsal: false },
    ...rest,
  };
};

describe("who may command a trial over its socket", () => {
  it.each<[string, TrialAccess, string, "allow" | "claim" | RegExp]>([
    ["the assigned wizard", access(), "next", "allow"],
    ["a wizard on another wizard's trial", access({ wizardId: "u-other" }), "next", /assigned to another wizard/],
    [
      "a wizard starting another wizard's trial",
      access({ wizardId: "u-other", status: "scheduled" }),
      "start",
      /assigned to another wizard/,
    ],
    [
      "a wizard stopping another wizard's robot (safety first)",
      access({ wizardId: "u-other" }),
      "emergency_stop",
      "allow",
    ],
    [
      "a wizard starting an unassigned trial claims it",
      access({ wizardId: null, status: "scheduled" }),
      "start",
      "claim",
    ],
    ["a wizard on an unassigned running trial", access({ wizardId: null }), "next", "allow"],
    ["an owner on a wizard's trial", access({ studyRole: "owner", wizardId: "u-other" }), "jump", "allow"],
    ["a researcher on a wizard's trial", access({ studyRole: "researcher", wizardId: "u-other" }), "abort", "allow"],
    [
      "a researcher starting an unassigned trial claims it too",
      access({ studyRole: "researcher", wizardId: null, status: "scheduled" }),
      "start",
      "claim",
    ],
    [
      "an owner starting an unassigned trial claims it",
      access({ studyRole: "owner", wizardId: null, status: "scheduled" }),
      "start",
      "claim",
    ],
    [
      "a researcher's next on an unassigned trial claims nothing",
      access({ studyRole: "researcher", wizardId: null }),
      "next",
      "allow",
    ],
    [
      "an owner starting another wizard's trial runs it without taking it over",
      access({ studyRole: "owner", wizardId: "u-other", status: "scheduled" }),
      "start",
      "allow",
    ],
    [
      "an observer",
      access({ studyRole: "observer" }),
      "next",
      /^As observer you may watch this trial but not run it\.$/,
    ],
    ["an observer's emergency stop", access({ studyRole: "observer" }), "emergency_stop", /As observer/],
    [
      "starting a trial in a draft study",
      access({ studyRole: "owner", studyStatus: "draft", status: "scheduled" }),
      "start",
      /still a draft: rehearse its experiments/,
    ],
    [
      "starting an unassigned trial in a completed study claims nothing",
      access({ studyStatus: "completed", wizardId: null, status: "scheduled" }),
      "start",
      /completed: its data is kept read-only/,
    ],
    [
      "starting a rehearsal in a draft study",
      access({
        studyStatus: "draft",
        status: "scheduled",
        trial: { wizardId: me, status: "scheduled", isRehearsal: true },
      }),
      "start",
      "allow",
    ],
    [
      "carrying on with a running trial once the study is completed",
      access({ studyStatus: "completed" }),
      "next",
      "allow",
    ],
    ["a removed member", access({ studyRole: null }), "next", /no longer a member/],
    ["a removed member's emergency stop", access({ studyRole: null }), "emergency_stop", /no longer a member/],
    ["a disabled account", access({ active: false, studyRole: "owner" }), "next", /no longer active/],
  ])("%s", (_name, who, kind, expected) => {
    const verdict = commandVerdict(who, kind);
    if (expected === "allow" || expected === "claim")
      expect(verdict).toEqual({ allow: true, claim: expected === "claim" });
    else expect(verdict.allow ? "allowed" : verdict.reason).toMatch(expected);
  });

  it.each<[string, TrialAccess, boolean]>([
    ["an observer", access({ studyRole: "observer" }), true],
    ["a wizard of another trial", access({ wizardId: "u-other" }), true],
    ["a removed member", access({ studyRole: null }), false],
  ])("annotating: %s → %s", (_name, who, allowed) => {
    expect(annotateVerdict(who).allow).toBe(allowed);
  });

  it.each<[string, TrialAccess, string]>([
    ["an observer of a running trial", access({ studyRole: "observer" }), "allow"],
    ["an observer of a paused trial", access({ studyRole: "observer", status: "paused" }), "allow"],
    ["an observer before the start", access({ studyRole: "observer", status: "scheduled" }), "has not started yet"],
    [
      "an observer after the end",
      access({ studyRole: "observer", status: "completed" }),
      "code it on its analysis page",
    ],
    ["an observer of an aborted trial", access({ studyRole: "observer", status: "aborted" }), "has ended"],
    ["a removed member", access({ studyRole: null }), "no longer a member"],
  ])("coding live: %s", (_name, who, expected) => {
    const verdict = codeVerdict(who);
    expect(verdict.allow ? "allow" : verdict.reason).toContain(expected);
  });
});

describe("who receives a trial's event log", () => {
  const blind = { conditionsHidden: false, resultsHidden: true };
  it.each<[string, TrialAccess, boolean]>([
    ["a researcher, finished trial", access({ studyRole: "researcher", status: "completed" }), true],
    [
      "a results-blinded researcher, finished trial",
      access({ studyRole: "researcher", blinding: blind, status: "completed" }),
      false,
    ],
    [
      "a results-blinded researcher, aborted trial",
      access({ studyRole: "researcher", blinding: blind, status: "aborted" }),
      false,
    ],
    ["a results-blinded researcher, live trial", access({ studyRole: "researcher", blinding: blind }), true],
    [
      "a results-blinded observer, paused trial",
      access({ studyRole: "observer", blinding: blind, status: "paused" }),
      true,
    ],
    ["a wizard (no data.read), finished trial", access({ status: "completed" }), false],
    ["a wizard, scheduled trial", access({ status: "scheduled" }), true],
    ["an owner, finished trial", access({ studyRole: "owner", status: "completed" }), true],
    ["a removed member, live trial", access({ studyRole: null }), false],
    ["a disabled owner, live trial", access({ studyRole: "owner", active: false }), false],
  ])("%s → %s", (_name, who, readable) => {
    expect(mayReadTrialLog(who)).toBe(readable);
  });
});

describe("who may watch a trial's robot camera", () => {
  const ENDED = "This trial has ended: its robot's camera ended with it.";
  it.each<[string, TrialAccess, boolean, string | null]>([
    ["an observer, live trial, watching", access({ studyRole: "observer" }), true, null],
    ["a wizard, paused trial, watching", access({ status: "paused" }), true, null],
    ["a researcher, finished trial, watching", access({ studyRole: "researcher", status: "completed" }), true, null],
    ["a wizard (no data.read), finished trial, watching", access({ status: "completed" }), true, ENDED],
    ["a wizard (no data.read), finished trial, stopping", access({ status: "completed" }), false, null],
    ["a removed member, watching", access({ studyRole: null }), true, "You are no longer a member of this study."],
    ["a removed member, stopping", access({ studyRole: null }), false, "You are no longer a member of this study."],
  ])("%s", (_name, who, watch, refusal) => {
    const verdict = cameraVerdict(who, watch);
    expect(verdict.allow ? null : verdict.reason).toBe(refusal);
  });
});

describe("who may replay a trial's robot commands on the simulated robot", () => {
  const blind = { conditionsHidden: false, resultsHidden: true };
  it.each<[string, TrialAccess, string | null]>([
    ["an observer, finished trial", access({ studyRole: "observer", status: "completed" }), null],
    ["a researcher, aborted trial", access({ studyRole: "researcher", status: "aborted" }), null],
    ["an owner, finished trial", access({ studyRole: "owner", status: "completed" }), null],
    [
      "a wizard (no data.read), finished trial",
      access({ status: "completed" }),
      "As a wizard of this study you may not do this.",
    ],
    [
      "a results-blinded researcher, finished trial",
      access({ studyRole: "researcher", blinding: blind, status: "completed" }),
      "This study hides results until it is marked completed (blinding).",
    ],
    [
      "a researcher, live trial",
      access({ studyRole: "researcher" }),
      "Only a finished trial can be replayed: this one has not ended yet.",
    ],
    [
      "a researcher, scheduled trial",
      access({ studyRole: "researcher", status: "scheduled" }),
      "Only a finished trial can be replayed: this one has not ended yet.",
    ],
    [
      "a removed member, finished trial",
      access({ studyRole: null, status: "completed" }),
      "You are no longer a member of this study.",
    ],
  ])("%s → %s", (_name, who, refusal) => {
    const verdict = replayVerdict(who);
    expect(verdict.allow ? null : verdict.reason).toBe(refusal);
  });
});

describe("which open sockets an access change concerns", () => {
  const socket = { userId: "u1", studyId: "s1", trialId: "t1" };
  it.each<[string, object, boolean]>([
    ["my membership in my study", { studyId: "s1", userId: "u1" }, true],
    ["someone else's membership in my study", { studyId: "s1", userId: "u2" }, false],
    ["my membership in another study", { studyId: "s2", userId: "u1" }, false],
    ["my study's settings or status", { studyId: "s1" }, true],
    ["another study's settings", { studyId: "s2" }, false],
    ["my account", { userId: "u1" }, true],
    ["another account", { userId: "u2" }, false],
    ["my trial's wizard", { trialId: "t1" }, true],
    ["another trial's wizard", { trialId: "t2" }, false],
    ["nothing named", {}, false],
  ])("%s → %s", (_name, change, touched) => {
    expect(touches(change, socket)).toBe(touched);
  });
});

describe("who may pass a live video signal to whom", () => {
  const wizard = access();
  const observer = (over: Parameters<typeof access>[0] = {}) =>
    access({ userId: "u-obs", studyRole: "observer", wizardId: me, ...over });
  it.each<[string, TrialAccess, TrialAccess, "allow" | RegExp]>([
    ["the wizard to an observer (an offer)", wizard, observer(), "allow"],
    ["an observer to the wizard (an answer)", observer(), wizard, "allow"],
    ["a researcher watching to the wizard", access({ userId: "u-r", studyRole: "researcher" }), wizard, "allow"],
    ["an observer to another observer", observer(), observer({ userId: "u-obs-2" }), /not between watchers/],
    [
      "another wizard of the study (who may not run it) to an observer",
      access({ userId: "u-w2", wizardId: me }),
      observer(),
      /not between watchers/,
    ],
    ["a removed member", observer({ studyRole: null }), wizard, /no longer a member/],
    ["to a removed member", wizard, observer({ studyRole: null }), /has left this trial/],
    [
      "to an observer once the trial has ended",
      access({ status: "completed" }),
      observer({ status: "completed" }),
      /has ended/,
    ],
  ])("%s", (_name, from, to, expected) => {
    const verdict = signalVerdict(from, to);
    if (expected === "allow") expect(verdict).toEqual({ allow: true, claim: false });
    else expect(!verdict.allow && verdict.reason).toMatch(expected);
  });
});
