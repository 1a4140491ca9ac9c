import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import { finish } from "../work";
import { checking, draftOf, exportExperiment, importExperiment } from "./exchange";
import type { DesignDraft } from "./types";

function ids(prefix = "new") {
  let n = 0;
  return () => `${prefix}-${++n}`;
}

const storyteller = storytellerDraft((key) => `db-${key}`);
/** A draft for the NAO6 with no description: what most cases here export and import. */
const nao6Draft = (name: string, steps: DesignDraft["steps"]): DesignDraft => ({
  name,
  description: "",
  robotId: "nao6-ros2",
  steps,
});

// Everything a naive writer or reader could trip on.
const awkward: DesignDraft = {
  name: 'Quotes " and \\ backslashes {braces}',
  description: "Line one\nLine two\ttabbed\r\n— ünïcødé 🤖 עברית \u0000 end",
  robotId: "nao6-ros2",
  steps: [
    {
      id: "a",
      name: "{{not a template}}",
      description: "$(rm -rf /); `echo hi` && 'single'",
      actions: [
        {
          id: "a1",
          type: "say",
          name: "",
          parameters: { text: '{"json": "inside"} \\n not a newline' },
          parallelGroup: "x",
        },
        {
          id: "a2",
          type: "wave",
          name: "Wave",
          parameters: {},
          parallelGroup: "x",
          note: "Only once the participant looks up.\nThen wait — “quietly”.",
        },
        {
          id: "a3",
          type: "nao6-ros2.custom",
          name: "Odd keys",
          parameters: { b: 1, "10": "ten", "2": "two", a: { z: [3, { y: 1, x: null }], "": true }, __proto__x: 0 },
          parallelGroup: null,
        },
        {
          id: "a4",
          type: "record_answer",
          name: "Answer",
          parameters: {
            options: [
              { id: "7", label: "Seven" },
              { id: "constructor", label: "Built" },
            ],
          },
          parallelGroup: null,
        },
        {
          id: "a5",
          type: "branch",
          name: "Go",
          parameters: { targets: { "7": "c", constructor: "a" } },
          parallelGroup: null,
        },
      ],
    },
    { id: "b", name: "Empty step", description: "", actions: [] },
    {
      id: "c",
      name: "Groups out of order",
      description: "",
      actions: [
        { id: "c1", type: "say", name: "Later group first", parameters: { text: "🙂" }, parallelGroup: "y" },
        { id: "c2", type: "nod", name: "", parameters: {}, parallelGroup: "x" },
        { id: "c3", type: "end_trial", name: "End", parameters: {}, parallelGroup: null },
      ],
    },
  ],
};

/** A draft with its ids replaced by their order of appearance, to compare structure across an import. */
function normalized(draft: DesignDraft) {
  const names = new Map<string, string>();
  const name = (id: string) => names.get(id) ?? names.set(id, `#${names.size + 1}`).get(id)!;
  draft.steps.forEach((s) => name(s.id));
  return JSON.parse(
    JSON.stringify({
      ...draft,
      steps: draft.steps.map((s) => ({
        ...s,
        id: name(s.id),
        after: s.after?.to === "step" ? { to: "step", stepId: name(s.after.stepId) } : (s.after ?? { to: "next" }),
        actions: s.actions.map((a) => ({
          ...a,
          id: name(a.id),
          parallelGroup: a.parallelGroup && name(a.parallelGroup),
          parameters:
            a.type === "branch"
              ? {
                  targets: Object.fromEntries(
                    Object.entries(a.parameters.targets as object).map(([k, v]) => [k, name(v)]),
                  ),
                }
              : a.parameters,
        })),
      })),
    }),
  );
}

function imported(text: string, newId = ids()): DesignDraft {
  const result = importExperiment(text, newId);
  if (!result.ok) throw new Error(JSON.stringify(result.problems));
  return result.draft;
}

describe("exporting and importing an experiment", () => {
  it.each([
    ["the Interactive Storyteller", storyteller],
    ["awkward text, odd keys, an empty step and groups", awkward],
  ])("%s survives a round trip byte for byte", (_, draft) => {
    const text = exportExperiment(draft);
    const again = imported(text);
    expect(exportExperiment(again)).toBe(text);
    expect(normalized(again)).toEqual(normalized(draft));
  });

  it("keeps where each step leads: a rejoin, an end, and the next step left out", () => {
    const draft = nao6Draft("Quiz", [
      { id: "u1", name: "Right", description: "", after: { to: "step", stepId: "u3" }, actions: [] },
      { id: "u2", name: "Wrong", description: "", after: { to: "end" }, actions: [] },
      { id: "u3", name: "Bye", description: "", after: { to: "next" }, actions: [] },
    ]);
    const text = exportExperiment(draft);
    expect(JSON.parse(text).steps.map((s: { after?: string }) => s.after)).toEqual(["@step-3", "end", undefined]);
    expect(normalized(imported(text))).toEqual(normalized(draft));
  });

  it("keeps time limits, their way on named by key like a step's after", () => {
    const question = { options: [{ id: "y", label: "yes" }] };
    const draft = nao6Draft("Timed", [
      {
        id: "u1",
        name: "Ask",
        description: "",
        timeLimit: { seconds: 30, after: { to: "step", stepId: "u3" } },
        actions: [
          {
            id: "a1",
            type: "record_answer",
            name: "",
            parameters: question,
            parallelGroup: null,
            timeLimit: { seconds: 10, after: { to: "end" } },
          },
        ],
      },
      { id: "u2", name: "Next", description: "", timeLimit: { seconds: 5, after: { to: "next" } }, actions: [] },
      { id: "u3", name: "Bye", description: "", actions: [] },
    ]);
    const file = JSON.parse(exportExperiment(draft));
    expect(file.steps.map((s: { timeLimit?: unknown }) => s.timeLimit)).toEqual([
      { seconds: 30, after: "@step-3" },
      { seconds: 5 },
      undefined,
    ]);
    expect(file.steps[0].actions[0].timeLimit).toEqual({ seconds: 10, after: "end" });
    const again = imported(JSON.stringify(file));
    expect(again.steps[0]!.timeLimit).toEqual({ seconds: 30, after: { to: "step", stepId: again.steps[2]!.id } });
    expect(again.steps[1]!.timeLimit).toEqual({ seconds: 5, after: { to: "next" } });
    expect(again.steps[0]!.actions[0]!.timeLimit).toEqual({ seconds: 10, after: { to: "end" } });
  });

  it("keeps loops, their steps named by key, on a step and on a time limit", () => {
    const draft = nao6Draft("Ask again", [
      {
        id: "u1",
        name: "Ask",
        description: "",
        after: { to: "again", stepId: "u1", times: 2, onward: { to: "next" } },
        timeLimit: { seconds: 10, after: { to: "again", stepId: "u1", times: 1, onward: { to: "end" } } },
        actions: [],
      },
      {
        id: "u2",
        name: "Bye",
        description: "",
        after: { to: "again", stepId: "u1", times: 3, onward: { to: "step", stepId: "u2" } },
        actions: [],
      },
    ]);
    const text = exportExperiment(draft);
    const file = JSON.parse(text);
    expect(file.steps.map((s: { after?: unknown }) => s.after)).toEqual([
      { again: "@step-1", times: 2 },
      { again: "@step-1", times: 3, onward: "@step-2" },
    ]);
    expect(file.steps[0].timeLimit).toEqual({ seconds: 10, after: { again: "@step-1", times: 1, onward: "end" } });
    const again = imported(text);
    const [ask, bye] = again.steps.map((step) => step.id);
    expect(again.steps.map((step) => step.after)).toEqual([
      { to: "again", stepId: ask, times: 2, onward: { to: "next" } },
      { to: "again", stepId: ask, times: 3, onward: { to: "step", stepId: bye } },
    ]);
    expect(again.steps[0]!.timeLimit!.after).toEqual({ to: "again", stepId: ask, times: 1, onward: { to: "end" } });
    expect(exportExperiment(again)).toBe(text);
  });

  it("keeps each condition's variant of an action and of a step, under the condition's name", () => {
    const draft = nao6Draft("Tutor", [
      {
        id: "u1",
        name: "Feedback",
        description: "",
        after: { to: "next" },
        actions: [
          {
            id: "a1",
            type: "say",
            name: "",
            parameters: { text: "Well done." },
            parallelGroup: null,
            variants: { "Warm tutor": { parameters: { text: "Well done, you are great!" } } },
          },
        ],
        variants: {
          Gestures: {
            actions: [
              { id: "a2", type: "wave", name: "", parameters: {}, parallelGroup: "g" },
              { id: "a3", type: "say", name: "", parameters: { text: "Well done." }, parallelGroup: "g" },
            ],
          },
        },
      },
    ]);
    const text = exportExperiment(draft);
    const file = JSON.parse(text);
    expect(file.steps[0].actions[0].variants).toEqual({
      "Warm tutor": { parameters: { text: "Well done, you are great!" } },
    });
    expect(file.steps[0].variants.Gestures.actions.map((a: { runTogether?: string }) => a.runTogether)).toEqual([
      "group-1",
      "group-1",
    ]);
    const again = imported(text);
    expect(exportExperiment(again)).toBe(text);
    // Fresh ids for the variant's actions, and for their run-together group (new-4).
    expect(again.steps[0]!.variants!.Gestures!.actions.map((a) => [a.id, a.parallelGroup])).toEqual([
      ["new-3", "new-4"],
      ["new-5", "new-4"],
    ]);
  });

  it("keeps where a wait's events lead, named by key like a step's after", () => {
    const draft = nao6Draft("Touch", [
      {
        id: "u1",
        name: "Wait",
        description: "",
        actions: [
          {
            id: "a1",
            type: "wait_for",
            name: "",
            parameters: {
              events: [
                { id: "t", event: "head_touched", after: { to: "step", stepId: "u3" } },
                { id: "r", event: "heard_ready", after: { to: "end" } },
                { id: "h", event: "hand_touched", after: { to: "next" } },
              ],
            },
            parallelGroup: null,
          },
        ],
      },
      { id: "u2", name: "Next", description: "", actions: [] },
      { id: "u3", name: "Greet", description: "", actions: [] },
    ]);
    const text = exportExperiment(draft);
    expect(JSON.parse(text).steps[0].actions[0].parameters.events).toEqual([
      { after: "@step-3", event: "head_touched", id: "t" },
      { after: "end", event: "heard_ready", id: "r" },
      { event: "hand_touched", id: "h" },
    ]);
    const again = imported(text);
    expect(again.steps[0]!.actions[0]!.parameters.events).toEqual([
      { id: "t", event: "head_touched", after: { to: "step", stepId: again.steps[2]!.id } },
      { id: "r", event: "heard_ready", after: { to: "end" } },
      { id: "h", event: "hand_touched", after: { to: "next" } },
    ]);
    expect(exportExperiment(again)).toBe(text);
    const broken = JSON.parse(text);
    broken.steps[0].actions[0].parameters.events[0].after = "@step-9";
    expect(importExperiment(JSON.stringify(broken), ids())).toMatchObject({
      ok: false,
      problems: [{ path: "$.steps[0].actions[0].parameters.events[0].after" }],
    });
  });

  it("names the steps a condition's variant of an action leads to by key, as the action's own, and checks them", () => {
    const step = (id: string, actions: DesignDraft["steps"][number]["actions"] = []) => ({
      id,
      name: `Step ${id.slice(1)}`,
      description: "",
      actions,
    });
    const draft = nao6Draft("Leads", [
      step("u1", [
        {
          id: "b",
          type: "branch",
          name: "",
          parameters: { targets: { yes: "u2", no: "u3" } },
          parallelGroup: null,
          // Another way in one condition; in another the branch waits for a touch instead.
          variants: {
            Swapped: { parameters: { targets: { yes: "u3", no: "u2" } } },
            Touch: {
              type: "wait_for",
              parameters: { events: [{ id: "t", event: "head_touched", after: { to: "step", stepId: "u3" } }] },
            },
          },
        },
        {
          id: "s",
          type: "say",
          name: "",
          parameters: { text: "Which one?" },
          parallelGroup: null,
          // A line in the shared protocol, a branch in one condition.
          variants: { Branching: { type: "branch", parameters: { targets: { go: "u3" } } } },
        },
      ]),
      step("u2"),
      step("u3"),
    ]);
    const text = exportExperiment(draft);
    expect(text).not.toMatch(/"u[123]"/);
    const [branch, say] = JSON.parse(text).steps[0].actions;
    expect(branch.variants).toEqual({
      Swapped: { parameters: { targets: { no: "@step-2", yes: "@step-3" } } },
      Touch: { parameters: { events: [{ after: "@step-3", event: "head_touched", id: "t" }] }, type: "wait_for" },
    });
    expect(say.variants).toEqual({ Branching: { parameters: { targets: { go: "@step-3" } }, type: "branch" } });
    const again = imported(text);
    const [, u2, u3] = again.steps.map((s) => s.id);
    const [b, s2] = again.steps[0]!.actions;
    expect(b!.parameters).toEqual({ targets: { yes: u2, no: u3 } });
    expect(b!.variants).toEqual({
      Swapped: { parameters: { targets: { yes: u3, no: u2 } } },
      Touch: {
        type: "wait_for",
        parameters: { events: [{ id: "t", event: "head_touched", after: { to: "step", stepId: u3 } }] },
      },
    });
    expect(s2!.variants).toEqual({ Branching: { type: "branch", parameters: { targets: { go: u3 } } } });
    expect(exportExperiment(again)).toBe(text);
    // A variant's target that names no step is a problem at its place, as the action's own would be.
    const broken = JSON.parse(text);
    broken.steps[0].actions[0].variants.Swapped.parameters.targets.yes = "@step-9";
    broken.steps[0].actions[1].variants.Branching.parameters.targets.go = "4f1c";
    broken.steps[0].actions[0].variants.Touch.parameters.events[0].after = "@step-7";
    expect(importExperiment(JSON.stringify(broken), ids())).toMatchObject({
      ok: false,
      problems: [
        {
          path: "$.steps[0].actions[0].variants.Swapped.parameters.targets.yes",
          message: '"@step-9" names no step of this file',
        },
        {
          path: "$.steps[0].actions[0].variants.Touch.parameters.events[0].after",
          message: '"@step-7" names no step of this file',
        },
        {
          path: "$.steps[0].actions[1].variants.Branching.parameters.targets.go",
          message: 'must name a step by "@" and its key, such as "@step-2"',
        },
      ],
    });
  });

  it("reads a version 1 file, whose steps each go on to the next", () => {
    const file = JSON.parse(exportExperiment(storyteller));
    file.formatVersion = 1;
    expect(normalized(imported(JSON.stringify(file)))).toEqual(normalized(storyteller));
  });

  it("writes a stable, readable file with no database ids in it", () => {
    const draft = nao6Draft("Tiny", [
      {
        id: "uuid-ask",
        name: "Ask",
        description: "",
        actions: [
          {
            id: "uuid-q",
            type: "record_answer",
            name: "Ready?",
            parameters: { prompt: "Ready?", options: [{ label: "Yes", id: "y" }] },
            parallelGroup: null,
          },
          {
            id: "uuid-b",
            type: "branch",
            name: "Go",
            parameters: { targets: { y: "uuid-bye", n: "uuid-deleted" } },
            parallelGroup: null,
          },
        ],
      },
      {
        id: "uuid-bye",
        name: "Bye",
        description: "",
        actions: [{ id: "uuid-w", type: "wave", name: "Wave", parameters: {}, parallelGroup: "uuid-g" }],
      },
    ]);
    expect(exportExperiment(draft)).toBe(
      [
        "{",
        '  "format": "hristudio.experiment",',
        '  "formatVersion": 5,',
        '  "experiment": {',
        '    "name": "Tiny",',
        '    "description": "",',
        '    "robot": "nao6-ros2"',
        "  },",
        '  "steps": [',
        "    {",
        '      "key": "step-1",',
        '      "name": "Ask",',
        '      "description": "",',
        '      "actions": [',
        "        {",
        '          "type": "record_answer",',
        '          "name": "Ready?",',
        '          "parameters": {',
        '            "options": [',
        "              {",
        '                "id": "y",',
        '                "label": "Yes"',
        "              }",
        "            ],",
        '            "prompt": "Ready?"',
        "          }",
        "        },",
        "        {",
        '          "type": "branch",',
        '          "name": "Go",',
        '          "parameters": {',
        '            "targets": {',
        '              "y": "@step-2"',
        "            }",
        "          }",
        "        }",
        "      ]",
        "    },",
        "    {",
        '      "key": "step-2",',
        '      "name": "Bye",',
        '      "description": "",',
        '      "actions": [',
        "        {",
        '          "type": "wave",',
        '          "name": "Wave",',
        '          "parameters": {},',
        '          "runTogether": "group-1"',
        "        }",
        "      ]",
        "    }",
        "  ]",
        "}",
        "",
      ].join("\n"),
    );
  });

  it("sorts parameters the same way whatever order they were written in, numbers-as-keys too", () => {
    const text = exportExperiment(awkward);
    expect(text.indexOf('"10": "ten"')).toBeLessThan(text.indexOf('"2": "two"'));
    expect(text.indexOf('"2": "two"')).toBeLessThan(text.indexOf('"__proto__x"'));
    expect(text).not.toMatch(/: "(?:[abc]\d?|x|y)"/); // no step, action or group id leaked
  });

  it("gives the imported experiment fresh ids, branch targets and groups included", () => {
    const draft = imported(exportExperiment(awkward));
    const [a, b, c] = draft.steps;
    expect([a!.id, b!.id, c!.id]).toEqual(["new-1", "new-2", "new-3"]);
    expect(a!.actions.map((x) => x.id)).toEqual(["new-4", "new-6", "new-7", "new-8", "new-9"]);
    expect(a!.actions[0]!.parallelGroup).toBe("new-5");
    expect(c!.actions.map((x) => x.parallelGroup)).toEqual(["new-11", "new-5", null]);
    expect(a!.actions[4]!.parameters).toEqual({ targets: { "7": "new-3", constructor: "new-1" } });
  });

  it("makes a checked file's steps one at a time, as they are read, with the ids an import gives", () => {
    const checked = finish(checking(exportExperiment(awkward)));
    if (!checked.ok) throw new Error("the file did not check");
    const newId = ids();
    const draft = draftOf(checked.file, newId);
    // Only the steps' own ids exist before the steps are read: their actions are made as each step is.
    expect(newId()).toBe("new-4");
    const [first] = draft.steps;
    expect(first!.actions.map((x) => x.id)).toEqual(["new-5", "new-7", "new-8", "new-9", "new-10"]);
  });

  it("keeps a parameter named __proto__ as a plain value", () => {
    const text = exportExperiment(awkward).replace('"__proto__x"', '"__proto__"');
    const draft = imported(text);
    const params = draft.steps[0]!.actions[2]!.parameters;
    expect(Object.hasOwn(params, "__proto__")).toBe(true);
    expect(Object.getPrototypeOf(params)).toBe(Object.prototype);
    expect(exportExperiment(draft)).toBe(text);
  });
});

describe("importing a bad file", () => {
  const valid = () => JSON.parse(exportExperiment(storyteller)) as Record<string, any>;
  const edit = (change: (file: Record<string, any>) => void) => {
    const file = valid();
    change(file);
    return JSON.stringify(file);
  };
  // Built as text: JSON.stringify itself gives up on nesting this deep.
  const deep = (change: (file: Record<string, any>) => void) =>
    edit(change).replace('"DEEP"', `${"[".repeat(5000)}${"]".repeat(5000)}`);
  const rows: Array<[string, string, Array<[string, string]>]> = [
    ["empty", "", [["$", "is not valid JSON: the file ends where a value was expected (line 1, column 1)"]]],
    ["not JSON", '{\n  "format": "hristudio.experiment",\n  oops\n}', [["$", "(line 3, column 3)"]]],
    ["null", "null", [["$", "must be an object"]]],
    ["a list at the top", "[]", [["$", "must be an object"]]],
    [
      "a plugin file",
      '{"robotId": "nao6-ros2", "actions": []}',
      [["$.format", "this is not an HRIStudio experiment file"]],
    ],
    [
      "a newer format",
      edit((f) => (f.formatVersion = 6)),
      [["$.formatVersion", "is 6: the file comes from a newer HRIStudio"]],
    ],
    ["a version as text", edit((f) => (f.formatVersion = "1")), [["$.formatVersion", "must be 1 or 2 or 3 or 4 or 5"]]],
    ["no steps", edit((f) => delete f.steps), [["$.steps", "must be a list"]]],
    ["no experiment", edit((f) => delete f.experiment), [["$.experiment", "must be an object"]]],
    ["a blank robot", edit((f) => (f.experiment.robot = " ")), [["$.experiment.robot", "must be a non-empty string"]]],
    [
      "a field the format does not have",
      edit((f) => (f.steps[1].colour = "red")),
      [["$.steps[1].colour", "is not part of an experiment file"]],
    ],
    ["a step that is not an object", edit((f) => (f.steps[0] = "intro")), [["$.steps[0]", "must be an object"]]],
    ["a step without a name", edit((f) => delete f.steps[2].name), [["$.steps[2].name", "must be a non-empty string"]]],
    [
      "two steps with one key",
      edit((f) => (f.steps[3].key = "step-1")),
      [
        ["$.steps[3].key", '"step-1" is already the key of step 1'],
        ["$.steps[2].actions[3].parameters.targets.correct", '"@step-4" names no step'],
      ],
    ],
    ["actions that are not a list", edit((f) => (f.steps[0].actions = {})), [["$.steps[0].actions", "must be a list"]]],
    [
      "an action type that is a number",
      edit((f) => (f.steps[2].actions[0].type = 7)),
      [["$.steps[2].actions[0].type", "must be a non-empty string"]],
    ],
    [
      "parameters that are null",
      edit((f) => (f.steps[0].actions[0].parameters = null)),
      [["$.steps[0].actions[0].parameters", "must be an object"]],
    ],
    [
      "parameters that are a list",
      edit((f) => (f.steps[0].actions[0].parameters = [])),
      [["$.steps[0].actions[0].parameters", "must be an object"]],
    ],
    [
      "a note for the wizard that is not text",
      edit((f) => (f.steps[0].actions[0].note = 7)),
      [["$.steps[0].actions[0].note", "must be a string"]],
    ],
    [
      "a note for the wizard too long",
      edit((f) => (f.steps[0].actions[0].note = "n".repeat(2001))),
      [["$.steps[0].actions[0].note", "must be at most 2000 characters (it has 2001)"]],
    ],
    [
      "an empty group name",
      edit((f) => (f.steps[0].actions[0].runTogether = "")),
      [["$.steps[0].actions[0].runTogether", "must be a non-empty string, or left out"]],
    ],
    [
      "an after to a missing step",
      edit((f) => (f.steps[1].after = "@step-9")),
      [["$.steps[1].after", '"@step-9" names no step of this file']],
    ],
    [
      "an after that is no step",
      edit((f) => (f.steps[1].after = "next")),
      [["$.steps[1].after", 'must be "end" or name a step']],
    ],
    [
      "an after in a version 1 file, which had none",
      edit((f) => {
        f.formatVersion = 1;
        f.steps[1].after = "end";
      }),
      [["$.steps[1].after", "is not part of an experiment file"]],
    ],
    [
      "a time limit of no time, leading to a missing step",
      edit((f) => (f.steps[1].timeLimit = { seconds: 0, after: "@step-9" })),
      [
        ["$.steps[1].timeLimit.seconds", "must be a number of seconds, more than 0 and at most 3600"],
        ["$.steps[1].timeLimit.after", '"@step-9" names no step of this file'],
      ],
    ],
    [
      "a time limit in a version 2 file, which had none",
      edit((f) => {
        f.formatVersion = 2;
        f.steps[2].actions[2].timeLimit = { seconds: 10 };
      }),
      [["$.steps[2].actions[2].timeLimit", "is not part of an experiment file"]],
    ],
    [
      "a loop in a version 3 file, which had none",
      edit((f) => {
        f.formatVersion = 3;
        f.steps[1].after = { again: "@step-1", times: 2 };
      }),
      [["$.steps[1].after", "is a loop, which files of version 3 cannot hold (loops came in version 4)"]],
    ],
    [
      "a loop to a missing step, for no time, into another loop",
      edit((f) => (f.steps[1].after = { again: "@step-9", times: 0, onward: { again: "@step-1", times: 1 } })),
      [
        ["$.steps[1].after.again", '"@step-9" names no step of this file'],
        ["$.steps[1].after.times", "must be a whole number of times, from 1 to 20"],
        ["$.steps[1].after.onward", "a loop cannot go on into another"],
      ],
    ],
    [
      "a branch to a missing step",
      edit((f) => (f.steps[2].actions[3].parameters.targets.correct = "@step-9")),
      [["$.steps[2].actions[3].parameters.targets.correct", '"@step-9" names no step of this file']],
    ],
    [
      "a branch to a database id",
      edit((f) => (f.steps[2].actions[3].parameters.targets.correct = "4f1c")),
      [["$.steps[2].actions[3].parameters.targets.correct", 'must name a step by "@" and its key']],
    ],
    [
      "a target under an odd option id",
      edit((f) => (f.steps[2].actions[3].parameters.targets = { "my answer": 3 })),
      [['$.steps[2].actions[3].parameters.targets["my answer"]', 'must name a step by "@"']],
    ],
    [
      "too many steps",
      edit(
        (f) => (f.steps = Array.from({ length: 501 }, (_, i) => ({ key: `step-${i + 1}`, name: "S", actions: [] }))),
      ),
      [["$.steps", "has 501 steps; an experiment can have at most 500"]],
    ],
    [
      "too many actions",
      edit((f) => (f.steps[1].actions = Array(501).fill({ type: "nod" }))),
      [["$.steps[1].actions", "has 501 actions; a step can have at most 500"]],
    ],
    [
      "more actions in all than a design may hold, every step within its own limit",
      edit(
        (f) =>
          (f.steps = Array.from({ length: 101 }, (_, i) => ({
            key: `step-${i + 1}`,
            name: "S",
            actions: Array(500).fill({ type: "nod" }),
          }))),
      ),
      [["$.steps", "The design has 50,500 actions; the limit is 50,000."]],
    ],
    [
      "a name too long",
      edit((f) => (f.experiment.name = "n".repeat(201))),
      [["$.experiment.name", "must be at most 200 characters (it has 201)"]],
    ],
    [
      "a text too long",
      edit((f) => (f.steps[0].actions[0].parameters.text = "t".repeat(5001))),
      [["$.steps[0].actions[0].parameters.text", "must be at most 5000 characters"]],
    ],
    [
      "parameters nested absurdly deep",
      deep((f) => (f.steps[0].actions[1].parameters = "DEEP")),
      [["$.steps[0].actions[1].parameters", "must be an object"]],
    ],
    [
      "a parameter nested absurdly deep",
      deep((f) => (f.steps[0].actions[1].parameters = { deep: "DEEP" })),
      [[`$.steps[0].actions[1].parameters.deep${"[0]".repeat(32)}`, "is nested more than 32 levels deep"]],
    ],
    [
      "a whole file nested absurdly deep",
      `${"[".repeat(1_000_000)}${"]".repeat(1_000_000)}`,
      [["$", "must be an object"]],
    ],
    [
      "a file over 2 MB",
      JSON.stringify({ format: "hristudio.experiment", padding: "é".repeat(1_100_000) }),
      [["$", "larger than 2 MB"]],
    ],
  ];

  it.each(rows)("%s", (_, text, expected) => {
    const result = importExperiment(text, ids());
    expect(result.ok).toBe(false);
    const problems = result.ok ? [] : result.problems;
    expect(problems.map((p) => p.path)).toEqual(expected.map(([path]) => path));
    problems.forEach((p, i) => expect(p.message).toContain(expected[i]![1]));
  });

  it("never throws, whatever part of a good file is cut off or replaced", () => {
    const text = exportExperiment(awkward);
    for (let end = 0; end < text.length; end += 7) expect(importExperiment(text.slice(0, end), ids()).ok).toBe(false);
    const paths: Array<Array<string | number>> = [];
    const visit = (value: unknown, path: Array<string | number>) => {
      paths.push(path);
      if (value && typeof value === "object")
        for (const [k, v] of Object.entries(value)) visit(v, [...path, Array.isArray(value) ? Number(k) : k]);
    };
    visit(JSON.parse(text), []);
    for (const path of paths.slice(1)) {
      for (const replacement of [null, 0, -1.5, true, "", "@step-1", [], {}, [null], { type: 1 }]) {
        const file = JSON.parse(text);
        const parent = path.slice(0, -1).reduce((o, k) => o[k], file);
        parent[path.at(-1)!] = replacement;
        const result = importExperiment(JSON.stringify(file), ids());
        if (result.ok) expect(() => exportExperiment(result.draft)).not.toThrow();
      }
    }
  });
});
