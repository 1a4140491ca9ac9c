import { describe, expect, it } from "vitest";
import { decide, type StudyRole } from "../access/policy";
import { blindingFor, blindTrial, BLINDED_NAME } from "./blinding";
import { readSettings } from "./settings";

const both = readSettings({ blinding: { conditionsFromWizards: true, resultsUntilComplete: true } });
const none = readSettings({});

describe("who a blind hides what from", () => {
  it.each<[StudyRole, string, boolean, boolean]>([
    ["owner", "active", false, false],
    ["researcher", "active", false, true],
    ["observer", "active", false, true],
    ["wizard", "active", true, false],
    ["researcher", "completed", false, false],
    ["observer", "archived", false, false],
    ["wizard", "completed", true, false],
  ])(
    "%s in an %s study with both blinds: conditions hidden %s, results hidden %s",
    (role, status, conditions, results) => {
      expect(blindingFor(role, both, status)).toEqual({ conditionsHidden: conditions, resultsHidden: results });
    },
  );

  it.each<[StudyRole, boolean]>([
    ["owner", false],
    ["researcher", false],
    ["wizard", false],
    ["observer", true],
  ])("the observers' blind hides conditions from a %s: %s", (role, hidden) => {
    const observers = readSettings({ blinding: { conditionsFromObservers: true } });
    expect(blindingFor(role, observers, "active").conditionsHidden).toBe(hidden);
  });

  it.each([
    ["experiment.read", false],
    ["data.read", false],
    ["trial.read", true],
    ["annotation.create", true],
  ] as const)("the policy, for a condition-blind observer, answers %s with %s", (op, allowed) => {
    const observers = readSettings({ blinding: { conditionsFromObservers: true } });
    const blinding = blindingFor("observer", observers, "active");
    expect(decide({ systemRole: "observer", studyRole: "observer", blinding }, op).allow).toBe(allowed);
  });

  it("hides nothing from anyone when the study has no blinds", () => {
    for (const role of ["owner", "researcher", "wizard", "observer"] as const)
      expect(blindingFor(role, none, "active")).toEqual({ conditionsHidden: false, resultsHidden: false });
  });

  it.each([
    ["wizard", "experiment.read", false],
    ["wizard", "trial.run", true],
    ["wizard", "participant.read", true],
    ["researcher", "data.read", false],
    ["researcher", "experiment.read", true],
    ["owner", "data.read", true],
  ] as const)("the policy, for a blinded %s, answers %s with %s", (role, op, allowed) => {
    expect(
      decide({ systemRole: "researcher", studyRole: role, blinding: blindingFor(role, both, "active") }, op).allow,
    ).toBe(allowed);
  });

  it("says why in words when a blind refuses", () => {
    const d = decide(
      { systemRole: "wizard", studyRole: "wizard", blinding: { conditionsHidden: true, resultsHidden: false } },
      "experiment.read",
    );
    expect(d).toMatchObject({
      allow: false,
      hidden: false,
      reason: expect.stringMatching(/hides its conditions from wizards/),
    });
  });

  it("strips a trial of everything that points at its condition", () => {
    const trial = {
      id: "t1",
      experimentId: "e1",
      experimentName: "NAO with gestures",
      versionId: "v1",
      version: 3,
      participantCode: "P001",
      protocol: {
        schemaVersion: 1,
        experiment: { id: "e1", name: "NAO with gestures", description: "gestures", robotId: "nao6-ros2" },
        steps: [],
      },
    };
    const blinded = blindTrial(trial);
    expect(JSON.stringify(blinded)).not.toMatch(/e1|v1|gestures/);
    expect(blinded).toMatchObject({
      id: "t1",
      participantCode: "P001",
      experimentName: BLINDED_NAME,
      protocol: { experiment: { robotId: "nao6-ros2" }, steps: [] },
    });
  });

  it("keeps the actions as the trial runs them, never which condition's variant each is", () => {
    const say = { id: "a1", type: "say", parameters: { text: "Well done, friend!" } };
    const trial = {
      protocol: {
        experiment: { id: "e1", name: "Tutor", description: "", robotId: "nao6-ros2" },
        steps: [{ id: "s1", name: "Feedback", actions: [{ ...say, variant: "Warm-tutor-QX7" }] }],
      },
    };
    const blinded = blindTrial(trial);
    expect(JSON.stringify(blinded)).not.toContain("Warm-tutor-QX7");
    expect(blinded.protocol.steps[0]!.actions).toEqual([say]);
  });
});
