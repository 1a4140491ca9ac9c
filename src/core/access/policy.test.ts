import { describe, expect, it } from "vitest";
import { type Blinding, NOT_BLINDED } from "../studies/blinding";
import { decide, runsAssigned, type StudyOperation, type StudyRole } from "./policy";

describe("who runs an assigned trial or session", () => {
  it.each<[string, StudyRole, string | null, boolean]>([
    ["a wizard, their own", "wizard", "me", true],
    ["a wizard, one assigned to nobody (starting it makes it theirs)", "wizard", null, true],
    ["a wizard, another wizard's", "wizard", "someone else", false],
    ["a researcher, anyone's", "researcher", "someone else", true],
    ["an owner, anyone's", "owner", "someone else", true],
  ])("%s", (_, role, assigned, runs) => {
    expect(runsAssigned(role, assigned, "me")).toBe(runs);
  });
});

describe("what a blind refuses an observer", () => {
  const conditions = { conditionsHidden: true, resultsHidden: false };
  const results = { conditionsHidden: false, resultsHidden: true };
  it.each<[string, Blinding, StudyOperation, boolean]>([
    ["blind to condition: the results", conditions, "data.read", false],
    ["blind to condition: the experiments", conditions, "experiment.read", false],
    ["blind to condition: a trial's recording, to code it afterwards", conditions, "recording.read", true],
    ["blind to condition: a code of their own", conditions, "annotation.create", true],
    ["blind to results: a trial's recording", results, "recording.read", false],
    ["not blind: a trial's recording", NOT_BLINDED, "recording.read", true],
  ])("%s: allowed %s", (_, blinding, op, allowed) => {
    expect(decide({ systemRole: "observer", studyRole: "observer", blinding }, op).allow).toBe(allowed);
  });
});
