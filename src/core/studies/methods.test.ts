import { describe, expect, it } from "vitest";
import type { DesignStep } from "../protocol/document";
import { snapshotOf } from "../protocol/snapshot";
import { type ConditionFacts, type StudyFacts, studyMethodsMarkdown, studyMethodsPlainText } from "./methods";

const say = (id: string, text: string) => ({ id, type: "say", name: "", parameters: { text }, parallelGroup: null });
const step = (id: string, name: string, actions: DesignStep["actions"]): DesignStep => ({
  id,
  name,
  description: "",
  actions,
});
const snapshot = (name: string, steps: DesignStep[]) =>
  snapshotOf({ id: name, name, description: "", robotId: "nao6-ros2", steps });

const greeting = step("g", "Greeting", [say("hi", "Hello, I am NAO.")]);
const goodbye = step("b", "Goodbye", [say("bye", "Goodbye!")]);

const condition = (over: Partial<ConditionFacts>): ConditionFacts => ({
  name: "Expressive",
  description: "",
  experiment: "Story with gestures",
  protocol: {
    version: 2,
    hash: "aaa111",
    snapshot: snapshot("Story with gestures", [
      greeting,
      step("s", "Story", [say("s1", "Once upon a time…"), { ...say("w", ""), type: "wave", parameters: {} }]),
      goodbye,
    ]),
  },
  enrolled: 3,
  completed: 2,
  withdrawn: 1,
  excluded: [{ reason: "declined consent", n: 0 }],
  steps: [
    { name: "Greeting", durationMs: { n: 2, median: 4000, min: 3000, max: 5000 } },
    { name: "Story", durationMs: { n: 1, median: 61_250, min: 61_250, max: 61_250 } },
    { name: "Goodbye", durationMs: null },
  ],
  fidelity: {
    trials: 2,
    meanFidelity: 87.5,
    sdFidelity: 17.68,
    withoutDeviation: 1,
    deviationsByKind: { skipped: 1, out_of_order: 0 },
  },
  ...over,
});

const still = condition({
  name: "Still",
  experiment: "Story standing still",
  protocol: {
    version: 1,
    hash: "bbb222",
    snapshot: snapshot("Story standing still", [
      greeting,
      // The still story may last 20 s: a time limit is a line of its condition's protocol.
      { ...step("s", "Story", [say("s1", "Once upon a time…")]), timeLimit: { seconds: 20, after: { to: "next" } } },
      goodbye,
    ]),
  },
  enrolled: 2,
  completed: 2,
  withdrawn: 0,
  excluded: [{ reason: "declined consent", n: 1 }],
  fidelity: { trials: 2, meanFidelity: 100, sdFidelity: 0, withoutDeviation: 2, deviationsByKind: {} },
});

const study: StudyFacts = {
  title: "Storytelling and memory",
  conditions: [condition({}), still],
  assignment: { strategy: "balanced", perCondition: 2, seed: "seed-42" },
  blinding: { conditionsFromWizards: true, resultsUntilComplete: false, conditionsFromObservers: false },
  robots: [
    {
      name: "Simulated NAO6",
      simulated: true,
      plugin: "NAO6 Robot",
      pluginVersion: "3.0.0",
      pluginHash: "ccc333",
      trials: 4,
    },
  ],
  questionnaires: [
    { name: "System Usability Scale (SUS)", timing: "after", items: 10, instrument: "sus", responses: 4 },
    { name: "Background", timing: "before", items: 2, instrument: null, responses: 1 },
  ],
  coding: [
    {
      name: "Gaze",
      version: 1,
      counted: "1 s slices, from when both observers had coded",
      sets: [{ name: "Looks at", pairs: [{ observers: ["Ann", "Bo"], kappa: 0.7322, slices: 120 }] }],
    },
  ],
  software: { version: "0.1.0" },
};

const plain = studyMethodsPlainText(study);

describe("the study's methods text says each fact", () => {
  it.each([
    ["the design", "The study had a between-subjects design: each participant took part in one condition."],
    ["n per condition", "“Expressive”: 3 enrolled, 2 completed, 1 withdrew; none excluded."],
    ["exclusions with their reasons", "“Still”: 2 enrolled, 2 completed, 0 withdrew; 1 excluded (1 declined consent)."],
    ["the assignment and its seed", "The assignment's seed was seed-42, from which it can be reproduced."],
    ["who was blind", "Wizards were blind to condition"],
    [
      "the robot as the trials ran it",
      "“Simulated NAO6” (simulated; plugin “NAO6 Robot”, version 3.0.0, SHA-256 ccc333; 4 trials)",
    ],
    ["each condition's published version", "“Still” ran version 1 of “Story standing still” (SHA-256 bbb222)"],
    [
      "the steps both share",
      "The conditions shared these steps (numbered as in “Expressive”):\n1. Greeting. The robot said “Hello, I am NAO.”",
    ],
    [
      "the differing line of one",
      "Only in Expressive\n2. Story. The robot said “Once upon a time…” Then the robot performed “Wave”.",
    ],
    [
      "the differing line of the other, with its time limit",
      "Only in Still\n2. Story. The robot said “Once upon a time…” If the step had not ended within 20 seconds, the trial went on to “Goodbye”.",
    ],
    [
      "step timings, median and range",
      "“Greeting” median 4.0 s, range 3.0–5.0 s (n = 2); “Story” median 61.3 s (n = 1).",
    ],
    ["a questionnaire's scoring reference", "(10 items; 4 responses), scored as published: odd items (answer − 1)"],
    ["a questionnaire without an instrument", "Before the trial: “Background” (2 items; 1 response)."],
    ["coding agreement", "“Looks at”: Cohen's κ = 0.73 between Ann and Bo (120 slices)."],
    [
      "what the kappa counted",
      "Observers coded with “Gaze” (version 1); agreement was counted in 1 s slices, from when both observers had coded:",
    ],
    [
      "fidelity and deviations",
      "“Expressive”: mean execution fidelity 87.5% (SD 17.7) over 2 trials; 1 of 2 without any deviation; deviations: 1 action skipped.",
    ],
    [
      "a condition without deviations",
      "“Still”: mean execution fidelity 100.0% (SD 0.0) over 2 trials; 2 of 2 without any deviation; no deviations.",
    ],
    ["the software's version", "generated with HRIStudio 0.1.0."],
  ])("%s", (_fact, sentence) => {
    expect(plain).toContain(sentence);
  });
});

/** The protocol with its last step going back to the first once, then ending. */
const looping = (protocol: NonNullable<ConditionFacts["protocol"]>) => {
  const steps = protocol.snapshot.steps.map((st, i, all) =>
    i === all.length - 1
      ? { ...st, after: { to: "again" as const, stepId: all[0]!.id, times: 1, onward: { to: "end" as const } } }
      : st,
  );
  return { ...protocol, snapshot: { ...protocol.snapshot, steps } };
};

describe("the study's design decides what is said", () => {
  it.each([
    {
      name: "within subjects",
      facts: { ...study, assignment: { strategy: "counterbalanced" as const, perCondition: 1, seed: "s" } },
      says: "within-subjects design: each participant took part in every condition",
    },
    {
      name: "one condition: its protocol in full, no assignment",
      facts: { ...study, conditions: [still] },
      says: "The study had one condition, “Still”: every participant followed the same protocol.",
      saysNot: "Assignment",
    },
    {
      name: "a loop, told once when every condition's protocol has it",
      facts: {
        ...study,
        conditions: [condition({}), still].map((c) => ({ ...c, protocol: looping(c.protocol!) })),
      },
      says: "Loops\n\nAfter “Goodbye”, the trial went back to “Greeting”, at most once, and then ended.",
      saysNot: "In “Still”: After",
    },
    {
      name: "a loop in one condition only, named with it",
      facts: { ...study, conditions: [condition({}), { ...still, protocol: looping(still.protocol!) }] },
      says: "In “Still”: After “Goodbye”, the trial went back to “Greeting”, at most once, and then ended.",
    },
    { name: "no loop: no Loops section", facts: study, says: "Protocol", saysNot: "Loops" },
    {
      name: "an unpublished experiment",
      facts: { ...study, conditions: [condition({}), { ...still, protocol: null }] },
      says: "“Still”: its experiment has not been published yet.",
    },
    { name: "no trial yet", facts: { ...study, robots: [] }, says: "No trial has run on a robot yet." },
    {
      name: "observers and coders blind to condition",
      facts: { ...study, blinding: { ...study.blinding, conditionsFromObservers: true } },
      says: "Observers and coders were blind to condition",
      saysNot: "were not blind",
    },
    {
      name: "no coding scheme: the section is left out",
      facts: { ...study, coding: [] },
      says: "Fidelity and deviations",
      saysNot: "Coding and agreement",
    },
    {
      name: "the researcher assigns: no seed to report",
      facts: { ...study, assignment: { strategy: "fixed" as const, perCondition: 1, seed: "s" } },
      says: "The researcher assigned each participant to a condition.",
      saysNot: "seed",
    },
  ])("$name", ({ facts, says, saysNot }) => {
    const text = studyMethodsPlainText(facts);
    expect(text).toContain(says);
    if (saysNot) expect(text).not.toContain(saysNot);
  });
});

it("the Markdown says the same with headings, and escapes the researcher's words", () => {
  const markdown = studyMethodsMarkdown({ ...study, title: "Gaze *and* memory" });
  expect(markdown).toContain("## Methods: Gaze \\*and\\* memory");
  expect(markdown).toContain("## Participants\n\n“Expressive”: 3 enrolled");
  expect(markdown).toContain("**Only in Still**\n2. **Story.**");
});

describe("the study's methods text of waits for the robot's senses", () => {
  const waiting = condition({
    name: "Touch",
    protocol: {
      version: 1,
      hash: "ccc333",
      events: [
        {
          id: "head_touched",
          name: "Head touched",
          topic: "/touch",
          messageType: "std_msgs/msg/Bool",
          when: { kind: "pressed", field: "data", equals: true },
        },
      ],
      snapshot: snapshot("Touch to start", [
        step("w", "Wait for a touch", [
          {
            id: "wait",
            type: "wait_for",
            name: "",
            parameters: { events: [{ id: "t", event: "head_touched", after: { to: "next" } }] },
            parallelGroup: null,
          },
        ]),
        goodbye,
      ]),
    },
  });

  it("has a Robot senses section naming each event awaited, its condition and its step", () => {
    const text = studyMethodsPlainText({ ...study, conditions: [waiting, still] });
    expect(text).toContain(
      "Robot senses\n\nIn “Touch”, the trial waited for the robot to sense “Head touched” (its field data became true, once per press) in “Wait for a touch”; the wizard could go on without it.",
    );
  });
});
