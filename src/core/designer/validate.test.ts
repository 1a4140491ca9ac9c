import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import { loadPlugin, type Plugin } from "../plugins";
import type { DesignAction, DesignDraft, After } from "./types";
import { hasErrors, validateDesign, type DesignIssue } from "./validate";

type ActionSpec = Partial<DesignAction> & { type: string };

// Steps s1, s2...; actions s1a1, s1a2... so a row reads like the issue list.
function draft(...steps: ActionSpec[][]): DesignDraft {
  return {
    name: "Test",
    description: "",
    robotId: "toy",
    steps: steps.map((actions, s) => ({
      id: `s${s + 1}`,
      name: `Step ${s + 1}`,
      description: "",
      actions: actions.map((a, i) => ({
        id: `s${s + 1}a${i + 1}`,
        name: "",
        parameters: {},
        parallelGroup: null,
        ...a,
      })),
    })),
  };
}

const say = (text: unknown = "Hello", extra: Partial<DesignAction> = {}): ActionSpec => ({
  type: "say",
  parameters: { text },
  ...extra,
});
const wave = (extra: Partial<DesignAction> = {}): ActionSpec => ({ type: "wave", ...extra });
const end: ActionSpec = { type: "end_trial" };
const question = (...labels: string[]): ActionSpec => ({
  type: "record_answer",
  parameters: { options: labels.map((label, i) => ({ id: `o${i + 1}`, label })) },
});
const branch = (targets: Record<string, unknown>): ActionSpec => ({ type: "branch", parameters: { targets } });

const summary = (issues: DesignIssue[]) =>
  issues.map((i) => [i.severity, i.code, i.actionId ?? i.stepId, i.parameter].filter(Boolean).join(" "));

// The plugin rows run against: it maps say and posture (standing only), has no arms.
const toy: Plugin = {
  robotId: "toy",
  name: "Toy robot",
  version: "1.0.0",
  pluginApiVersion: "1.0",
  actions: [
    {
      id: "speak",
      name: "Speak",
      category: "speech",
      parameterSchema: {
        type: "object",
        properties: { words: { type: "string", maxLength: 20 } },
        required: ["words"],
      },
    },
    { id: "stand", name: "Stand", category: "posture", parameterSchema: { type: "object", properties: {} } },
    {
      id: "beep",
      name: "Beep",
      category: "sound",
      parameterSchema: {
        type: "object",
        properties: { volume: { type: "number", title: "Volume", minimum: 0, maximum: 1 } },
        required: ["volume"],
      },
    },
  ],
  abstract: {
    say: { action: "speak", parameters: { words: "{{text}}" } },
    posture: { action: "stand", when: { posture: "stand" } },
  },
  unsupported: [{ action: "wave", reason: "It has no arms." }],
};

describe("validateDesign", () => {
  const rows: Array<[string, DesignDraft, string[], (Plugin | null)?]> = [
    ["a straight run of steps", draft([say()], [say(), end]), []],
    ["falling off the last step ends the trial", draft([say()], [say()]), []],
    ["no steps", draft(), ["error no_steps"]],
    ["a step with no actions", draft([say()], [], [say()]), ["error empty_step s2"]],
    ["an unknown block", draft([{ type: "dance" }]), ["error unknown_block s1a1"]],
    ["another robot's action", draft([{ type: "pepper.bow" }]), ["error unknown_block s1a1"], toy],
    [
      "a robot action without its plugin",
      draft([{ type: "toy.beep", parameters: { volume: 1 } }]),
      ["error unknown_block s1a1"],
    ],
    ["a robot action with its plugin", draft([{ type: "toy.beep", parameters: { volume: 1 } }]), [], toy],
    [
      "a robot action with a bad parameter",
      draft([{ type: "toy.beep", parameters: { volume: 2 } }]),
      ["error parameter s1a1 volume"],
      toy,
    ],
    ["say without text", draft([{ type: "say" }]), ["error parameter s1a1 text"]],
    ["say with empty text", draft([say("")]), ["error parameter s1a1 text"]],
    [
      "a misspelt parameter",
      draft([say("Hi", { parameters: { text: "Hi", txet: "Hi" } })]),
      ["error parameter s1a1 txet"],
    ],
    ["a question with one answer", draft([question("Yes")]), ["error parameter s1a1 options"]],
    ["a branch with no question before it", draft([say(), branch({})], [say()]), ["error branch_without_answer s1a2"]],
    [
      "a branch separated from its question",
      draft([question("Yes", "No"), say(), branch({ o1: "s2", o2: "s2" })], [say()]),
      ["error branch_without_answer s1a3"],
    ],
    [
      "a branch answer leading nowhere",
      draft([question("Yes", "No"), branch({ o1: "s2" })], [say()]),
      ["error branch_target_missing s1a2 targets"],
    ],
    [
      "a branch answer leading to a deleted step",
      draft([question("Yes", "No"), branch({ o1: "s2", o2: "gone" })], [say()]),
      ["error branch_target_missing s1a2 targets"],
    ],
    [
      "a branch to the steps after it",
      draft([question("Yes", "No"), branch({ o1: "s2", o2: "s3" })], [say(), end], [say()]),
      [],
    ],
    ["a step after an end is never reached", draft([say(), end], [say()]), ["error unreachable_step s2"]],
    [
      "a step reached only when a question's time runs out is reached",
      draft(
        [{ ...question("Yes", "No"), timeLimit: { seconds: 10, after: { to: "step", stepId: "s3" } } }, end],
        [say(), end],
        [say()],
      ),
      ["error unreachable_step s2"],
    ],
    [
      "a time limit on an action that is no question",
      draft([say("Hi", { timeLimit: { seconds: 5, after: { to: "end" } } })]),
      ["error time_limit_not_question s1a1"],
    ],
    [
      "a time limit leading to a deleted step",
      draft([{ ...question("Yes", "No"), timeLimit: { seconds: 10, after: { to: "step", stepId: "gone" } } }]),
      ["error after_target_missing s1"],
    ],
    [
      "a step skipped by every answer",
      draft([question("Yes", "No"), branch({ o1: "s3", o2: "s3" })], [say()], [say()]),
      ["error unreachable_step s2"],
    ],
    [
      "a broken branch falls through rather than cascading",
      draft([question("Yes", "No"), branch({ o1: "s3" })], [say(), end], [say()]),
      ["error branch_target_missing s1a2 targets"],
    ],
    [
      "a branch that always loops back",
      draft([say()], [question("Again", "Once more"), branch({ o1: "s1", o2: "s2" })], [say()]),
      ["error no_end s1", "error unreachable_step s3"],
    ],
    ["a loop with a way out", draft([say()], [question("Again", "Done"), branch({ o1: "s1", o2: "s3" })], [say()]), []],
    ["actions after an end", draft([say(), end, wave(), end]), ["warning after_end s1a3", "warning after_end s1a4"]],
    ["the same answer twice", draft([question("Yes", " yes", "No")]), ["warning duplicate_option s1a1 options"]],
    ["running together with a neighbour", draft([say("Hi", { parallelGroup: "g" }), wave({ parallelGroup: "g" })]), []],
    [
      "running together with no neighbour",
      draft([say("Hi", { parallelGroup: "g" }), wave(), say("Bye", { parallelGroup: "g" })]),
      ["warning run_together_alone s1a1", "warning run_together_alone s1a3"],
    ],
    ["an action the robot cannot do", draft([wave()]), ["warning unsupported_on_robot s1a1"], toy],
    [
      "a value the robot does not support",
      draft([{ type: "posture", parameters: { posture: "sit" } }]),
      ["error parameter s1a1 posture"],
      toy,
    ],
    [
      "a problem only the robot's own action has",
      draft([say("This sentence is far too long for the toy")]),
      ["error parameter s1a1 words"],
      toy,
    ],
    ["a problem reported once, not again by the robot", draft([say("")]), ["error parameter s1a1 text"], toy],
    [
      "issues in step order, then action order",
      draft([wave({ parallelGroup: "g" }), say("")], [], [{ type: "dance" }, end, say()]),
      [
        "warning run_together_alone s1a1",
        "warning unsupported_on_robot s1a1",
        "error parameter s1a2 text",
        "error empty_step s2",
        "error unknown_block s3a1",
        "warning after_end s3a3",
      ],
      toy,
    ],
  ];
  it.each(rows)("%s", (_, design, expected, plugin = null) =>
    expect(summary(validateDesign(design, plugin))).toEqual(expected),
  );

  it("speaks to researchers, naming steps, actions and fields as the designer shows them", () => {
    const design = draft([say("", { name: "Greeting" }), wave({ name: "Wave hello" })], [say(), end], [say()]);
    design.steps[2]!.name = "Bonus";
    expect(validateDesign(design, toy).map((i) => i.message)).toEqual([
      '"Greeting": "Text" must not be empty.',
      '"Wave hello" cannot run on Toy robot: It has no arms.',
      'Step "Bonus" can never be reached: the steps before it end the trial or branch elsewhere, and no branch leads to it.',
    ]);
    expect(validateDesign(draft([question("Yes", "No"), branch({ o1: "s1" })]), null).map((i) => i.message)).toEqual([
      '"Branch": choose the step the answer "No" leads to.',
    ]);
    expect(
      validateDesign(draft([say()], [question("Again", "More"), branch({ o1: "s1", o2: "s1" })]), null)[0]!.message,
    ).toBe(
      'The trial can never end from step "Step 1": every way on loops back without reaching an "End trial" block or a step that leads to the end.',
    );
  });

  it("tells errors from warnings", () => {
    expect(hasErrors(validateDesign(draft([say(), end, wave()]), null))).toBe(false);
    expect(hasErrors(validateDesign(draft([say("")]), null))).toBe(true);
  });
});

describe("where steps lead (after)", () => {
  // s1 asks with three answers; s2–s4 are the answers' steps; s5 is where they meet.
  const quiz = (afters: Array<After | undefined>) => {
    const d = draft(
      [question("Mars", "Venus", "Silent"), branch({ o1: "s2", o2: "s3", o3: "s4" })],
      [say("Right")],
      [say("Not quite")],
      [say("Take your time")],
      [say("Bye")],
    );
    afters.forEach((after, i) => {
      if (after) d.steps[i]!.after = after;
    });
    return d;
  };
  const toGoodbye: After = { to: "step", stepId: "s5" };

  it.each<[string, DesignDraft, string[]]>([
    ["answers that rejoin a shared step", quiz([undefined, toGoodbye, toGoodbye, toGoodbye]), []],
    [
      "answers that fall through into each other (the natural build, each going on to the next)",
      quiz([]),
      ["warning answer_falls_through s2", "warning answer_falls_through s3"],
    ],
    ["the last answer's step may fall through to the shared step", quiz([undefined, toGoodbye, toGoodbye]), []],
    ["an answer's step that ends the trial", quiz([undefined, { to: "end" }, toGoodbye, toGoodbye]), []],
    [
      "an after to a step that is gone",
      quiz([undefined, { to: "step", stepId: "gone" }, toGoodbye, toGoodbye]),
      ["error after_target_missing s2"],
    ],
    [
      "a step after one that ends the trial, reached by nothing",
      (() => {
        const d = draft([say()], [say()]);
        d.steps[0]!.after = { to: "end" };
        return d;
      })(),
      ["error unreachable_step s2"],
    ],
    [
      "a loop with a way out (a wrong answer asks again)",
      quiz([undefined, toGoodbye, { to: "step", stepId: "s1" }, toGoodbye]),
      [],
    ],
    [
      "a loop with no way out",
      (() => {
        const d = draft([say()], [say()]);
        d.steps[1]!.after = { to: "step", stepId: "s1" };
        return d;
      })(),
      ["error no_end s1"],
    ],
  ])("%s", (_name, design, expected) => {
    expect(summary(validateDesign(design, null))).toEqual(expected);
  });

  it("says which answer's response would follow, in the researcher's words", () => {
    const [first] = validateDesign(quiz([]), null);
    expect(first!.message).toBe(
      'After step "Step 2" (the answer "Mars"), the trial goes on to step "Step 3", the step for the answer "Venus", so both responses are given. Set where step "Step 2" leads, for example to the step where the answers meet.',
    );
  });
});

describe("the Interactive Storyteller", () => {
  const storyteller = storytellerDraft();
  const plugin = (file: string) => {
    const loaded = loadPlugin(file, readFileSync(`plugins/${file}`, "utf8"));
    if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
    return loaded.value;
  };

  it("is a sound design on its own and on NAO6", () => {
    expect(validateDesign(storyteller, null)).toEqual([]);
    expect(validateDesign(storyteller, plugin("nao6-ros2.json"))).toEqual([]);
  });

  it("on a TurtleBot3 is sound but cannot speak or gesture: warnings only", () => {
    const issues = validateDesign(storyteller, plugin("turtlebot3-burger.json"));
    expect(issues.length).toBe(9);
    expect(issues.every((i) => i.code === "unsupported_on_robot")).toBe(true);
    expect(hasErrors(issues)).toBe(false);
  });
});

describe("on this server's ways to the robot", () => {
  const nao = loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8"));
  if (!nao.ok) throw new Error(JSON.stringify(nao.errors));
  const postures = draft([{ type: "posture", parameters: { posture: "sit" } }, { type: "nao6-ros2.rest" }, say()]);
  const rosbridgeOnly = { rosbridge: true, simulator: true, ssh: false, http: false };

  it("says which actions cannot run here, and why, as a warning", () => {
    const issues = validateDesign(postures, nao.value, rosbridgeOnly);
    expect(issues.map((i) => [i.severity, i.code, i.actionId, i.message])).toEqual(
      ["s1a1", "s1a2"].map((id, n) => [
        "warning",
        "unsupported_on_robot",
        id,
        `"${["Posture", "Rest"][n]}" cannot run on NAO6 Robot (ROS2 Integration): it needs SSH to the robot, and this server has no SSH address for it: set HRI_ROBOT_SSH_HOST (see docs/robot-setup.md)`,
      ]),
    );
  });

  it("says nothing when the server reaches the robot every way, or is not asked", () => {
    expect(validateDesign(postures, nao.value, { ...rosbridgeOnly, ssh: true })).toEqual([]);
    expect(validateDesign(postures, nao.value)).toEqual([]);
  });
});

describe("bounded loops", () => {
  // s1, s2, s3 each say a line; `afters` sets where each leads.
  const steps = (...afters: Array<After | undefined>) => {
    const d = draft([say()], [say()], [say()]);
    afters.forEach((after, i) => {
      if (after) d.steps[i]!.after = after;
    });
    return d;
  };
  const again = (stepId: string, onward: After & { to: "next" | "step" | "end" }): After => ({
    to: "again",
    stepId,
    times: 2,
    onward,
  });

  it.each<[string, DesignDraft, string[]]>([
    ["a step that asks again at most twice, then goes on", steps(undefined, again("s2", { to: "next" })), []],
    ["back to an earlier step, then on past the loop", steps(undefined, again("s1", { to: "step", stepId: "s3" })), []],
    [
      "back to an earlier step, then the end",
      steps(undefined, again("s1", { to: "end" }), { to: "end" }),
      ["error unreachable_step s3"],
    ],
    [
      "its last time leads back inside the loop: no way out (told once, not again as an endless trial)",
      steps(undefined, again("s1", { to: "step", stepId: "s1" })),
      ["error loop_no_way_out s2", "error unreachable_step s3"],
    ],
    [
      "its last time leads to a step that goes round again",
      steps(undefined, again("s1", { to: "next" }), { to: "step", stepId: "s2" }),
      ["error loop_no_way_out s2"],
    ],
    ["a loop that goes forward", steps(again("s2", { to: "next" })), ["error loop_forward s1"]],
    [
      "a loop back to a step that is gone",
      steps(undefined, again("gone", { to: "next" })),
      ["error after_target_missing s2"],
    ],
    [
      "a time limit whose loop has no way out",
      (() => {
        const d = steps();
        d.steps[1]!.timeLimit = { seconds: 10, after: again("s1", { to: "step", stepId: "s2" }) };
        return d;
      })(),
      ["error loop_no_way_out s2"],
    ],
  ])("%s", (_name, design, expected) => {
    expect(summary(validateDesign(design, null))).toEqual(expected);
  });

  it("names the loop's steps and where its last time leads", () => {
    const design = steps(undefined, again("s1", { to: "step", stepId: "s1" }));
    expect(validateDesign(design, null)[0]!.message).toEqual(
      'The loop from step "Step 2" back to step "Step 1" has no way out: after going back 2 times it goes on to step "Step 1", which is inside the loop. Choose where it goes after its last time: a step outside the loop, or the end of the trial.',
    );
  });
});

describe("a Wait for", () => {
  const waitFor = (events: Array<[string, After]>, extra: Partial<DesignAction> = {}): ActionSpec => ({
    type: "wait_for",
    parameters: { events: events.map(([event, after], i) => ({ id: `e${i + 1}`, event, after })) },
    ...extra,
  });
  const sensing: Plugin = {
    ...toy,
    events: [
      {
        id: "head_touched",
        name: "Head touched",
        topic: "/touch",
        messageType: "std_msgs/msg/Bool",
        when: { kind: "pressed", field: "data", equals: true },
      },
    ],
  };
  const toStep = (stepId: string): After => ({ to: "step", stepId });
  const limit = { seconds: 20, after: toStep("s2") };

  it.each<[string, DesignDraft, string[], Plugin | null]>([
    ["an event leading to a step", draft([waitFor([["head_touched", toStep("s2")]])], [say()]), [], null],
    ["a time limit alone", draft([waitFor([], { timeLimit: limit })], [say()]), [], null],
    ["nothing to wait for", draft([waitFor([])], [say()]), ["error wait_for_nothing s1a1 events"], null],
    [
      "an event with no step chosen",
      draft([waitFor([["head_touched", { to: "step", stepId: "" }]])], [say()]),
      ["error wait_target_missing s1a1 events"],
      null,
    ],
    [
      "an event leading to a step that is gone",
      draft([waitFor([["head_touched", toStep("gone")]])], [say()]),
      ["error wait_target_missing s1a1 events"],
      null,
    ],
    [
      "a step reached only by an event is reachable",
      (() => {
        const d = draft([waitFor([["head_touched", toStep("s2")]])], [say()]);
        d.steps[0]!.after = { to: "end" };
        return d;
      })(),
      [],
      null,
    ],
    ["an event the robot senses", draft([waitFor([["head_touched", toStep("s2")]])], [say()]), [], sensing],
    [
      "an event the robot does not sense",
      draft([waitFor([["heard_ready", toStep("s2")]])], [say()]),
      ["warning unsupported_on_robot s1a1"],
      sensing,
    ],
  ])("%s", (_name, design, expected, plugin) => {
    expect(summary(validateDesign(design, plugin))).toEqual(expected);
  });

  it("says what is missing in the researcher's words", () => {
    expect(validateDesign(draft([waitFor([])], [say()]), null)[0]!.message).toBe(
      '"Wait for" waits for nothing: choose at least one event the robot senses, or a time limit.',
    );
    expect(validateDesign(draft([waitFor([["heard_ready", toStep("s2")]])], [say()]), sensing)[0]!.message).toBe(
      '"Wait for" cannot run on Toy robot: Toy robot (plugin 1.0.0) does not sense "heard_ready" (it senses: head_touched)',
    );
  });
});
