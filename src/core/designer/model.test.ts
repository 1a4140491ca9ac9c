import { describe, expect, it } from "vitest";
import { commands } from "./model";
import { execute, redo, startHistory, undo, type Command } from "./history";
import { DesignerError } from "./draft";
import type { DesignDraft } from "./types";

function ids() {
  let n = 0;
  return () => `id-${++n}`;
}

const say = (text: string) => ({ type: "say", name: "Say", parameters: { text } });

function draft(): DesignDraft {
  return {
    name: "Storyteller",
    description: "",
    robotId: "nao6-ros2",
    steps: [
      {
        id: "intro",
        name: "Introduction",
        description: "",
        actions: [
          { id: "hello", type: "say", name: "Hello", parameters: { text: "Hello" }, parallelGroup: "g" },
          { id: "wave", type: "wave", name: "Wave", parameters: {}, parallelGroup: "g" },
          { id: "bow", type: "nao6-ros2.bow", name: "Bow", parameters: {}, parallelGroup: null },
        ],
      },
      { id: "story", name: "Story", description: "", actions: [{ id: "tale", ...say("Once"), parallelGroup: null }] },
      { id: "end", name: "End", description: "", actions: [] },
    ],
  };
}

const shape = (d: DesignDraft) =>
  d.steps.map(
    (s) => `${s.id}: ${s.actions.map((a) => a.id + (a.parallelGroup ? `[${a.parallelGroup}]` : "")).join(" ")}`,
  );

describe("designer commands", () => {
  const cases: Array<[string, Command, string[] | ((d: DesignDraft) => unknown), unknown?]> = [
    [
      "add step at the end",
      commands.addStep("Recall"),
      shape,
      ["intro: hello[g] wave[g] bow", "story: tale", "end: ", "id-1: "],
    ],
    [
      "add step at a position",
      commands.addStep("Recall", 1),
      (d) => d.steps.map((s) => s.name),
      ["Introduction", "Recall", "Story", "End"],
    ],
    [
      "edit step",
      commands.updateStep("story", { name: "The story", description: "Kai on Mars" }),
      (d) => [d.steps[1]!.name, d.steps[1]!.description],
      ["The story", "Kai on Mars"],
    ],
    ["delete step", commands.removeStep("story"), (d) => d.steps.map((s) => s.id), ["intro", "end"]],
    ["move step up", commands.moveStep("end", 0), (d) => d.steps.map((s) => s.id), ["end", "intro", "story"]],
    [
      "move step past the end stays last",
      commands.moveStep("intro", 99),
      (d) => d.steps.map((s) => s.id),
      ["story", "end", "intro"],
    ],
    [
      "add action into a step",
      commands.addAction("end", 0, { type: "end_trial", name: "End", parameters: {} }),
      shape,
      ["intro: hello[g] wave[g] bow", "story: tale", "end: id-1"],
    ],
    [
      "add action between two",
      commands.addAction("intro", 2, say("Hi")),
      shape,
      ["intro: hello[g] wave[g] id-1 bow", "story: tale", "end: "],
    ],
    ["delete action", commands.removeAction("bow"), shape, ["intro: hello[g] wave[g]", "story: tale", "end: "]],
    [
      "move action within its step leaves its group",
      commands.moveAction("hello", "intro", 2),
      shape,
      ["intro: wave bow hello", "story: tale", "end: "],
    ],
    [
      "move action to another step",
      commands.moveAction("bow", "story", 0),
      shape,
      ["intro: hello[g] wave[g]", "story: bow tale", "end: "],
    ],
    [
      "move action into an empty step",
      commands.moveAction("tale", "end", 5),
      shape,
      ["intro: hello[g] wave[g] bow", "story: ", "end: tale"],
    ],
    ["rename action", commands.renameAction("bow", "Deep bow"), (d) => d.steps[0]!.actions[2]!.name, "Deep bow"],
    [
      "write a note for the wizard",
      commands.setNote("bow", "Only if the participant smiles."),
      (d) => d.steps[0]!.actions[2]!.note,
      "Only if the participant smiles.",
    ],
    ["empty the note: none is kept", commands.setNote("bow", "  "), (d) => "note" in d.steps[0]!.actions[2]!, false],
    [
      "set parameter",
      commands.setParameter("hello", "text", 'She said "hi" {{x}} $(rm -rf /)'),
      (d) => d.steps[0]!.actions[0]!.parameters,
      { text: 'She said "hi" {{x}} $(rm -rf /)' },
    ],
    [
      "clear parameter",
      commands.setParameter("hello", "text", undefined),
      (d) => d.steps[0]!.actions[0]!.parameters,
      {},
    ],
    [
      "run together with the action above joins its group",
      commands.setRunTogether("bow", true),
      shape,
      ["intro: hello[g] wave[g] bow[g]", "story: tale", "end: "],
    ],
    [
      "run on its own",
      commands.setRunTogether("wave", false),
      shape,
      ["intro: hello wave bow", "story: tale", "end: "],
    ],
    ["change robot", commands.setRobot("pepper"), (d) => d.robotId, "pepper"],
    [
      "lead a step to another",
      commands.setAfter("intro", { to: "step", stepId: "end" }),
      (d) => d.steps[0]!.after,
      { to: "step", stepId: "end" },
    ],
    ["lead a step to the end", commands.setAfter("story", { to: "end" }), (d) => d.steps[1]!.after, { to: "end" }],
    [
      "give a step a time limit",
      commands.setStepTimeLimit("story", { seconds: 30, after: { to: "end" } }),
      (d) => d.steps[1]!.timeLimit,
      { seconds: 30, after: { to: "end" } },
    ],
    ["take it away: none is kept", commands.setStepTimeLimit("story", null), (d) => "timeLimit" in d.steps[1]!, false],
    [
      "give a question a time limit",
      commands.setAnswerTimeLimit("bow", { seconds: 10, after: { to: "step", stepId: "end" } }),
      (d) => d.steps[0]!.actions[2]!.timeLimit,
      { seconds: 10, after: { to: "step", stepId: "end" } },
    ],
    ["rename experiment", commands.setDetails({ name: "Storyteller v2" }), (d) => d.name, "Storyteller v2"],
    [
      "vary an action for a condition",
      commands.setVariant("tale", "Warm", { parameters: { text: "Once, friend" } }),
      (d) => d.steps[1]!.actions[0]!.variants,
      { Warm: { parameters: { text: "Once, friend" } } },
    ],
    [
      "leave a condition to the shared action: no variant is none kept",
      commands.setVariant("tale", "Warm", null),
      (d) => "variants" in d.steps[1]!.actions[0]!,
      false,
    ],
  ];

  it.each(cases)("%s, and undo restores the draft exactly", (_label, command, read, expected) => {
    const before = startHistory(draft());
    const after = execute(before, command, ids());
    expect(typeof read === "function" ? read(after.present) : null).toEqual(expected);
    expect(undo(after).present).toEqual(draft());
    expect(redo(undo(after)).present).toEqual(after.present);
  });

  it("a new group starts when two lone actions run together, and leaving the middle splits the rest off", () => {
    let h = startHistory(draft());
    h = execute(h, commands.addAction("story", 1, { type: "look_down", name: "Look", parameters: {} }, "look"), ids());
    h = execute(h, commands.setRunTogether("look", true), ids());
    expect(shape(h.present)[1]).toBe("story: tale[id-1] look[id-1]");
    h = execute(h, commands.addAction("intro", 2, say("and"), "and"), ids());
    h = execute(h, commands.setRunTogether("and", true), ids());
    h = execute(h, commands.setRunTogether("bow", true), ids());
    expect(shape(h.present)[0]).toBe("intro: hello[g] wave[g] and[g] bow[g]");
    h = execute(h, commands.setRunTogether("wave", false), () => "g2");
    expect(shape(h.present)[0]).toBe("intro: hello wave and[g2] bow[g2]");
  });

  it("creates a step for an answer from the branch itself and points the answer at it", () => {
    let h = startHistory(draft());
    h = execute(
      h,
      commands.addAction("story", 1, { type: "branch", name: "Branch", parameters: { targets: {} } }, "branch"),
      ids(),
    );
    h = execute(h, commands.addStepForAnswer("branch", "correct", "Response — correct"), () => "new-step");
    expect(h.present.steps.at(-1)).toMatchObject({ id: "new-step", name: "Response — correct" });
    expect(h.present.steps[1]!.actions[1]!.parameters).toEqual({ targets: { correct: "new-step" } });
    h = execute(h, commands.setBranchTarget("branch", "correct", null), ids());
    expect(h.present.steps[1]!.actions[1]!.parameters).toEqual({ targets: {} });
    h = undo(undo(h));
    expect(h.present.steps.map((s) => s.id)).toEqual(["intro", "story", "end"]);
  });

  it.each([
    ["a question", "record_answer"],
    ["a branch", "branch"],
  ])("never starts %s together with the action above, nor an action together with it", (_, type) => {
    const d = draft();
    d.steps[0]!.actions.splice(2, 0, { id: "choice", type, name: "Choice", parameters: {}, parallelGroup: null });
    const h = startHistory(d);
    for (const id of ["choice", "bow"])
      expect(() => execute(h, commands.setRunTogether(id, true), ids())).toThrow(/waits for the wizard's choice/);
  });

  it("refuses commands about blocks that are gone, in words, and leaves the draft untouched", () => {
    const h = startHistory(draft());
    const refusals: Command[] = [
      commands.moveAction("nope", "intro", 0),
      commands.moveAction("bow", "nope", 0),
      commands.removeStep("nope"),
      commands.setParameter("nope", "text", "x"),
      commands.setBranchTarget("bow", "a", "nope"),
      commands.setRunTogether("hello", true),
      commands.setAfter("intro", { to: "step", stepId: "nope" }),
      commands.setAfter("nope", { to: "end" }),
    ];
    for (const c of refusals) expect(() => execute(h, c, ids())).toThrow(DesignerError);
    expect(h.present).toEqual(draft());
  });

  it("typing into one field undoes as one step; another field starts a new one", () => {
    let h = startHistory(draft());
    for (const text of ["H", "He", "Hel"]) h = execute(h, commands.setParameter("hello", "text", text), ids());
    h = execute(h, commands.renameAction("hello", "Greeting"), ids());
    expect(h.past.map((p) => p.label)).toEqual(["set text", "rename action"]);
    expect(undo(undo(h)).present).toEqual(draft());
    expect(undo(h).present.steps[0]!.actions[0]!.parameters).toEqual({ text: "Hel" });
  });

  it("a command that changes nothing adds nothing to undo; a new command clears redo", () => {
    let h = startHistory(draft());
    h = execute(h, commands.moveStep("intro", 0), ids());
    expect(h.past).toHaveLength(0);
    h = execute(h, commands.removeStep("end"), ids());
    h = undo(h);
    expect(h.future.map((f) => f.label)).toEqual(["delete step"]);
    h = execute(h, commands.renameAction("bow", "Bow"), ids());
    expect(h.future).toHaveLength(0);
    expect(h.past.map((p) => p.label)).toEqual(["rename action"]);
    expect(undo(startHistory(draft())).present).toEqual(draft());
    expect(redo(startHistory(draft())).present).toEqual(draft());
  });
});

describe("a step's own actions in a condition", () => {
  const warmWave = { id: "warm-wave", type: "wave", name: "Wave", parameters: {}, parallelGroup: "w" };
  // The Storyteller with a story whose line varies, and a step that already has its own actions in two conditions.
  const varied = (): DesignDraft => {
    const d = draft();
    d.steps[1]!.actions[0]!.variants = { Warm: { parameters: { text: "Once, friend" } } };
    d.steps.push({
      id: "varied",
      name: "Varied",
      description: "",
      actions: [],
      variants: {
        Warm: { actions: [{ id: "warm-hi", ...say("Hello"), parallelGroup: "w" }, warmWave] },
        Plain: { actions: [] },
      },
    });
    return d;
  };

  it.each<[string, Command, (d: DesignDraft) => unknown, unknown]>([
    [
      "own: a copy of the step's actions with new ids, their groups kept",
      commands.setStepVariant("intro", "Warm", true),
      (d) => d.steps[0]!.variants,
      {
        Warm: {
          actions: [
            { id: "id-1", type: "say", name: "Hello", parameters: { text: "Hello" }, parallelGroup: "g" },
            { id: "id-2", type: "wave", name: "Wave", parameters: {}, parallelGroup: "g" },
            { id: "id-3", type: "nao6-ros2.bow", name: "Bow", parameters: {}, parallelGroup: null },
          ],
        },
      },
    ],
    [
      "own, of a step whose action varies: the copy is the shared action, without variants of its own",
      commands.setStepVariant("story", "Plain", true),
      (d) => d.steps[1]!.variants,
      { Plain: { actions: [{ id: "id-1", ...say("Once"), parallelGroup: null }] } },
    ],
    [
      "the text of one of its actions edited",
      commands.setStepVariantParameter("varied", "Warm", "warm-hi", "text", "Hello, friend"),
      (d) => d.steps[3]!.variants,
      {
        Warm: { actions: [{ id: "warm-hi", ...say("Hello, friend"), parallelGroup: "w" }, warmWave] },
        Plain: { actions: [] },
      },
    ],
    [
      "one of its actions removed: the group of one left is no group",
      commands.removeStepVariantAction("varied", "Warm", "warm-hi"),
      (d) => d.steps[3]!.variants?.Warm,
      { actions: [{ ...warmWave, parallelGroup: null }] },
    ],
    [
      "not own: that condition runs the step's actions",
      commands.setStepVariant("varied", "Warm", false),
      (d) => d.steps[3]!.variants,
      { Plain: { actions: [] } },
    ],
  ])("%s, and undo restores the draft exactly", (_label, command, read, expected) => {
    const after = execute(startHistory(varied()), command, ids());
    expect(read(after.present)).toEqual(expected);
    expect(undo(after).present).toEqual(varied());
    expect(redo(undo(after)).present).toEqual(after.present);
  });

  it("keeps no variants once the last condition runs the step's actions, and ticking what is ticked changes nothing", () => {
    let h = startHistory(varied());
    h = execute(h, commands.setStepVariant("varied", "Warm", false), ids());
    h = execute(h, commands.setStepVariant("varied", "Plain", false), ids());
    expect("variants" in h.present.steps[3]!).toBe(false);
    expect(h.past.map((p) => p.label)).toEqual(["share step with Warm", "share step with Plain"]);
    expect(execute(h, commands.setStepVariant("varied", "Plain", false), ids())).toBe(h);
  });

  it("types into one action's text as one undo, and refuses an action or a condition that is gone, in words", () => {
    let h = startHistory(varied());
    for (const text of ["H", "Hi"])
      h = execute(h, commands.setStepVariantParameter("varied", "Warm", "warm-hi", "text", text), ids());
    expect(h.past.map((p) => p.label)).toEqual(["set text in Warm"]);
    expect(() => execute(h, commands.removeStepVariantAction("varied", "Warm", "nope"), ids())).toThrow(
      'That action is no longer in this step\'s actions in "Warm".',
    );
    expect(() => execute(h, commands.removeStepVariantAction("intro", "Warm", "hello"), ids())).toThrow(
      'This step has no actions of its own in "Warm".',
    );
  });
});
