import { describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../protocol/snapshot";
import { diffProtocols } from "./diff";

type Snapshot = ProtocolSnapshot;
const act = (
  id: string,
  type: string,
  name: string,
  parameters: Record<string, unknown> = {},
  parallelGroup: string | null = null,
) => ({ id, type, name, parameters, parallelGroup });

const base: Snapshot = {
  schemaVersion: 5 as const,
  experiment: { id: "exp", name: "Storyteller", description: "Kai on Mars", robotId: "nao6-ros2" },
  steps: [
    {
      id: "intro",
      name: "Intro",
      description: "A greeting",
      actions: [act("greet", "say", "Greeting", { text: "Hello." }, "g1"), act("wave", "wave", "Wave", {}, "g1")],
    },
    {
      id: "story",
      name: "Story",
      description: "",
      actions: [
        act("tell", "say", "Tell", { text: "Kai had been on Mars for six days." }),
        act("look", "look_down", "Look down"),
      ],
    },
    {
      id: "recall",
      name: "Recall",
      description: "",
      actions: [
        act("ask", "record_answer", "Answer", {
          prompt: "Color?",
          options: [
            { id: "right", label: "red" },
            { id: "wrong", label: "other" },
          ],
        }),
        act("route", "branch", "Respond", { targets: { right: "yes", wrong: "no" } }),
      ],
    },
    { id: "yes", name: "Correct", description: "", actions: [act("end1", "end_trial", "End")] },
    { id: "no", name: "Incorrect", description: "", actions: [act("end2", "end_trial", "")] },
  ],
};

const step = (s: Snapshot, id: string) => s.steps.find((x) => x.id === id)!;
const action = (s: Snapshot, id: string) => s.steps.flatMap((x) => x.actions).find((a) => a.id === id)!;

describe("diffProtocols", () => {
  const rows: Array<[string, (s: Snapshot) => void, string[]]> = [
    ["identical versions", () => {}, []],
    [
      "the same parameters written in another key order",
      (s) =>
        (action(s, "ask").parameters = {
          options: [
            { label: "red", id: "right" },
            { label: "other", id: "wrong" },
          ],
          prompt: "Color?",
        }),
      [],
    ],
    [
      "a run-together group renamed, still the same actions",
      (s) => step(s, "intro").actions.forEach((a) => (a.parallelGroup = "other")),
      [],
    ],
    [
      "experiment details",
      (s) => (s.experiment = { ...s.experiment, name: "Storyteller 2", description: "", robotId: "pepper-ros2" }),
      [
        'changed experiment: Experiment renamed from "Storyteller" to "Storyteller 2"',
        'changed experiment: Experiment description changed from "Kai on Mars" to ""',
        'changed experiment: Robot changed from "nao6-ros2" to "pepper-ros2"',
      ],
    ],
    [
      "a note for the wizard added, changed and removed",
      (s) => {
        action(s, "greet").note = "Smile first.";
        action(s, "tell").note = "Slowly.";
      },
      [
        'changed action: Action "Greeting" in "Intro": note for the wizard added: "Smile first."',
        'changed action: Action "Tell" in "Story": note for the wizard added: "Slowly."',
      ],
    ],
    [
      "a step added",
      (s) =>
        s.steps.splice(1, 0, {
          id: "hold",
          name: "Pause",
          description: "",
          actions: [act("p", "pause", "Hold", { seconds: 2 })],
        }),
      ['added step: Step "Pause" added at position 2', 'added action: Action "Hold" added to "Pause" at position 1'],
    ],
    [
      "where a step leads, set and changed",
      (s) => {
        s.steps[0]!.after = { to: "end" };
        s.steps[1]!.after = { to: "next" };
      },
      ['changed step: Step "Intro" now leads to the end of the trial (it led to "Story")'],
    ],
    [
      "a step that now goes round a loop",
      (s) => {
        s.steps[0]!.after = { to: "again", stepId: s.steps[0]!.id, times: 3, onward: { to: "next" } };
      },
      ['changed step: Step "Intro" now leads to "Intro" again, at most 3 times, then "Story" (it led to "Story")'],
    ],
    [
      "a step removed with its actions",
      (s) => s.steps.splice(1, 1),
      [
        'removed step: Step "Story" removed',
        'removed action: Action "Tell" removed from "Story"',
        'removed action: Action "Look down" removed from "Story"',
      ],
    ],
    [
      "a step renamed and described",
      (s) => Object.assign(step(s, "intro"), { name: "Introduction", description: "The robot says hello" }),
      [
        'changed step: Step "Intro" renamed to "Introduction"',
        'changed step: Step "Introduction": description changed from "A greeting" to "The robot says hello"',
      ],
    ],
    [
      "a step moved forward",
      (s) => s.steps.unshift(...s.steps.splice(2, 1)),
      ['moved step: Step "Recall" moved from position 3 to 1'],
    ],
    [
      "two steps swapped",
      (s) => s.steps.push(s.steps.splice(3, 1)[0]!),
      ['moved step: Step "Correct" moved from position 4 to 5'],
    ],
    [
      "a text changed",
      (s) => (action(s, "greet").parameters.text = "Hello there."),
      ['changed action: Action "Greeting" in "Intro": text changed from "Hello." to "Hello there."'],
    ],
    [
      "a long text, shortened",
      (s) =>
        (action(s, "tell").parameters.text =
          "Kai had been on the Martian surface for six days. On the seventh morning, she walked to the crater."),
      [
        'changed action: Action "Tell" in "Story": text changed from "Kai had been on Mars for six days." to "Kai had been on the Martian surface for six days. On the seventh morning, she …',
      ],
    ],
    [
      "parameters set and removed",
      (s) => {
        action(s, "look").parameters.angle = 10;
        delete action(s, "greet").parameters.text;
      },
      [
        'changed action: Action "Greeting" in "Intro": text removed (was "Hello.")',
        'changed action: Action "Look down" in "Story": angle set to 10',
      ],
    ],
    [
      "an action moved to another step",
      (s) => step(s, "story").actions.push(step(s, "intro").actions.pop()!),
      [
        'changed action: Actions that run together in "Intro" changed from "Greeting" + "Wave" to none',
        'moved action: Action "Wave" moved from "Intro" to "Story"',
      ],
    ],
    [
      "actions reordered in a step",
      (s) => step(s, "story").actions.reverse(),
      ['moved action: Action "Tell" in "Story" moved from position 1 to 2'],
    ],
    [
      "actions renamed, retyped, removed and added",
      (s) => {
        Object.assign(action(s, "end2"), { name: "Finish" });
        Object.assign(action(s, "look"), { type: "nao6-ros2.look_at_floor" });
        step(s, "yes").actions = [
          act("thanks", "say", "Thanks", { text: "Thank you!" }),
          act("end1", "end_trial", "End"),
        ];
        step(s, "intro").actions.splice(1, 1);
      },
      [
        'removed action: Action "Wave" removed from "Intro"',
        'changed action: Actions that run together in "Intro" changed from "Greeting" + "Wave" to none',
        'changed action: Action "Look down" in "Story": type changed from "look_down" to "nao6-ros2.look_at_floor"',
        'added action: Action "Thanks" added to "Correct" at position 1',
        'changed action: Action "end_trial" in "Incorrect" renamed to "Finish"',
      ],
    ],
    [
      "actions set to run together",
      (s) => step(s, "story").actions.forEach((a) => (a.parallelGroup = "g2")),
      ['changed action: Actions that run together in "Story" changed from none to "Tell" + "Look down"'],
    ],
    [
      "a branch answer sent elsewhere, another dropped",
      (s) => (action(s, "route").parameters.targets = { right: "no" }),
      [
        'changed action: Action "Respond" in "Recall": answer "red" goes to "Incorrect" instead of "Correct"',
        'changed action: Action "Respond" in "Recall": answer "other" no longer goes to "Incorrect"',
      ],
    ],
    [
      "an answer added, with its branch",
      (s) => {
        (action(s, "ask").parameters.options as object[]).push({ id: "unsure", label: "not sure" });
        (action(s, "route").parameters.targets as Record<string, string>).unsure = "story";
      },
      [
        'changed action: Action "Answer" in "Recall": options changed from [{"id":"right","label":"red"},{"id":"wrong","label":"other"}] to [{"id":"right","label":"red"},{"id":"wrong","label":"other"},{"id":"unsure","la…',
        'changed action: Action "Respond" in "Recall": answer "not sure" now goes to "Story"',
      ],
    ],
  ];

  it.each(rows)("%s", (_, change, expected) => {
    const after = structuredClone(base);
    change(after);
    expect(diffProtocols(base, after).map((l) => `${l.kind} ${l.what}: ${l.text}`)).toEqual(expected);
  });

  it("says how a note for the wizard changed or that it was removed", () => {
    const was = structuredClone(base);
    action(was, "greet").note = "Smile first.";
    action(was, "tell").note = "Slowly.";
    const now = structuredClone(was);
    action(now, "greet").note = "Smile, then speak.";
    delete action(now, "tell").note;
    expect(diffProtocols(was, now).map((l) => l.text)).toEqual([
      'Action "Greeting" in "Intro": note for the wizard changed from "Smile first." to "Smile, then speak."',
      'Action "Tell" in "Story": note for the wizard removed',
    ]);
  });

  it("reads the other way round too", () => {
    const after = structuredClone(base);
    after.steps.splice(1, 0, { id: "hold", name: "Pause", description: "", actions: [] });
    expect(diffProtocols(after, base)).toEqual([{ kind: "removed", what: "step", text: 'Step "Pause" removed' }]);
  });
});
