import { describe, expect, it } from "vitest";
import { rehearse } from "../trial/rehearse";
import { hashCanonical } from "./canonical";
import { type DesignDraft, DOCUMENT_VERSION, snapshotSchema } from "./document";
import { snapshotOf } from "./snapshot";
import { idsInTwoSteps, inCondition, lackingVariants, unknownConditions } from "./variants";

// A tutor study's one difference between its conditions: the feedback line, and the whole goodbye step.
const tutor = (): DesignDraft => ({
  name: "Tutor",
  description: "",
  robotId: "nao6-ros2",
  steps: [
    {
      id: "feedback",
      name: "Feedback",
      description: "",
      after: { to: "next" },
      actions: [
        { id: "hello", type: "say", name: "", parameters: { text: "Hello" }, parallelGroup: null },
        {
          id: "praise",
          type: "say",
          name: "",
          parameters: { text: "Well done." },
          parallelGroup: null,
          variants: {
            Warm: { parameters: { text: "Well done, you are doing great!" } },
            Gesture: { type: "wave", parameters: { hand: "right" } },
          },
        },
      ],
    },
    {
      id: "bye",
      name: "Goodbye",
      description: "",
      after: { to: "next" },
      actions: [{ id: "bye-say", type: "say", name: "", parameters: { text: "Bye" }, parallelGroup: null }],
      variants: {
        Warm: {
          actions: [
            {
              id: "bye-warm",
              type: "say",
              name: "",
              parameters: { text: "See you soon, friend" },
              parallelGroup: null,
            },
          ],
        },
      },
    },
  ],
});

const ran = (condition: string | null) =>
  inCondition(tutor(), condition).steps.map((s) =>
    s.actions.map((a) => [a.id, a.type, a.parameters.text ?? a.parameters.hand, a.variant ?? null]),
  );

describe("the protocol a trial in a condition runs", () => {
  it.each<[string | null, unknown[]]>([
    [
      "Warm",
      [
        [
          ["hello", "say", "Hello", null],
          ["praise", "say", "Well done, you are doing great!", "Warm"],
        ],
        [["bye-warm", "say", "See you soon, friend", "Warm"]],
      ],
    ],
    [
      "Gesture",
      [
        [
          ["hello", "say", "Hello", null],
          ["praise", "wave", "right", "Gesture"],
        ],
        [["bye-say", "say", "Bye", null]],
      ],
    ],
    // A condition with no variant anywhere, and a trial of no condition (a rehearsal as the design): the shared design.
    [
      "Plain",
      [
        [
          ["hello", "say", "Hello", null],
          ["praise", "say", "Well done.", null],
        ],
        [["bye-say", "say", "Bye", null]],
      ],
    ],
    [
      null,
      [
        [
          ["hello", "say", "Hello", null],
          ["praise", "say", "Well done.", null],
        ],
        [["bye-say", "say", "Bye", null]],
      ],
    ],
  ])("in %s", (condition, actions) => {
    expect(ran(condition)).toEqual(actions);
  });

  it.each<[string | null, string[]]>([
    ["Warm", ["hello: Hello", "praise: Well done, you are doing great!", "bye-warm: See you soon, friend"]],
    ["Gesture", ["hello: Hello", "praise: wave", "bye-say: Bye"]],
    [null, ["hello: Hello", "praise: Well done.", "bye-say: Bye"]],
  ])("walked by the trial engine in %s, each action as that condition runs it", (condition, done) => {
    const walked = rehearse(inCondition(tutor(), condition)).steps.flatMap((s) => s.units.flat());
    expect(walked.map((a) => `${a.id}: ${a.parameters.text ?? a.type}`)).toEqual(done);
  });

  it("holds no variant of any condition: the trial and the wizard's page see one protocol", () => {
    const text = JSON.stringify(inCondition(tutor(), "Gesture"));
    expect(text).not.toContain("variants");
    expect(text).not.toContain("Warm");
  });
});

describe("the conditions of a design's variants", () => {
  it.each<[string[], unknown[]]>([
    [
      ["Warm", "Gesture", "Plain"],
      [
        { stepId: "feedback", actionId: "praise", conditions: ["Plain"] },
        { stepId: "bye", conditions: ["Gesture", "Plain"] },
      ],
    ],
    [["Warm"], []],
  ])("lacking a variant among %j", (conditions, lacking) => {
    expect(lackingVariants(tutor().steps, conditions)).toEqual(lacking);
  });

  it.each<[string[], string[]]>([
    [["Warm", "Gesture"], []],
    [["Warm"], ["Gesture"]],
    [[], ["Warm", "Gesture"]],
  ])("named by no condition among %j: %j", (conditions, unknown) => {
    expect(unknownConditions(tutor().steps, conditions)).toEqual(unknown);
  });
});

describe("variants in the published version", () => {
  const published = () => snapshotOf({ ...tutor(), id: "exp-1" });

  it("are part of the document of today's version", () => {
    expect(DOCUMENT_VERSION).toBe(5);
    expect(snapshotSchema.safeParse(published()).success).toBe(true);
  });

  it.each<[string, (d: DesignDraft) => void]>([
    ["an action's variant's text", (d) => (d.steps[0]!.actions[1]!.variants!.Warm!.parameters.text = "Great!")],
    ["an action's variant's type", (d) => (d.steps[0]!.actions[1]!.variants!.Gesture!.type = "nod")],
    ["a condition's name", (d) => (d.steps[1]!.variants = { Kind: d.steps[1]!.variants!.Warm! })],
    ["a step's variant's action", (d) => (d.steps[1]!.variants!.Warm!.actions[0]!.parameters.text = "Ciao")],
    ["a variant left out", (d) => delete d.steps[0]!.actions[1]!.variants!.Gesture],
  ])("change the hash when %s changes", (_, change) => {
    const draft = tutor();
    change(draft);
    expect(hashCanonical(snapshotOf({ ...draft, id: "exp-1" }))).not.toBe(hashCanonical(published()));
  });

  it("are left out of a design that has none, which hashes as it did before variants", () => {
    const plain = tutor();
    delete plain.steps[0]!.actions[1]!.variants;
    delete plain.steps[1]!.variants;
    expect(JSON.stringify(snapshotOf({ ...plain, id: "exp-1" }))).not.toContain("variants");
  });
});

describe("action ids a trial could not tell apart", () => {
  const step = (id: string, actions: string[], variant: string[] = []) => ({
    id,
    actions: actions.map((a) => ({ id: a })),
    ...(variant.length && { variants: { Warm: { actions: variant.map((a) => ({ id: a })) } } }),
  });

  it.each<[string, Parameters<typeof idsInTwoSteps>[0], string[]]>([
    ["a step's variant reusing its step's own ids: only one of them runs", [step("s1", ["a"], ["a", "b"])], []],
    ["a step's variant taking another step's action id", [step("s1", ["a"]), step("s2", ["b"], ["a"])], ["a"]],
    ["two steps' own actions sharing an id", [step("s1", ["a"]), step("s2", ["a"])], ["a"]],
    ["new actions, with no id yet", [step("s1", []), { id: "s2", actions: [{}, {}] }], []],
  ])("%s", (_, steps, repeated) => {
    expect(idsInTwoSteps(steps)).toEqual(repeated);
  });
});
