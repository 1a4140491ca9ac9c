import { describe, expect, it } from "vitest";
import { storytellerDraft } from "../../server/seed/storyteller";
import type { DesignStep } from "./document";
import { type MethodsInput, methodsMarkdown, methodsPlainText } from "./methods";
import { snapshotOf } from "./snapshot";

const HASH = "3f1c0e9a7b5d2468ace013579bdf2468ace013579bdf2468ace013579bdf2468";

const storyteller: MethodsInput = {
  snapshot: snapshotOf({ ...storytellerDraft(), id: "exp-1" }),
  version: 3,
  hash: HASH,
  robot: { name: "NAO6 Robot (ROS2 Integration)", pluginVersion: "3.0.0" },
  conditions: [
    { name: "Expressive", description: "Gestures with the story", experiment: "Interactive Storyteller" },
    { name: "Still", description: "", experiment: "Still storyteller" },
  ],
  assignment: { strategy: "balanced", perCondition: 2 },
  questionnaires: [
    { name: "Background", timing: "before", items: 4, instrument: null },
    { name: "System Usability Scale (SUS)", timing: "after", items: 10, instrument: "sus" },
    { name: "Robot impressions", timing: "after", items: 24, instrument: "godspeed" },
  ],
};

const say = (id: string, text: string) => ({ id, type: "say", name: "", parameters: { text }, parallelGroup: null });
const step = (id: string, name: string, actions: DesignStep["actions"], after?: DesignStep["after"]): DesignStep => ({
  id,
  name,
  description: "",
  actions,
  ...(after ? { after } : {}),
});

// A three-way question whose answers rejoin "Goodbye", which ends the trial.
const rejoining: MethodsInput = {
  ...storyteller,
  snapshot: snapshotOf({
    id: "exp-2",
    name: "Snack choice",
    description: "",
    robotId: "nao6-ros2",
    steps: [
      step("ask", "Ask", [
        say("q", "Which snack would you like?"),
        {
          id: "rec",
          type: "record_answer",
          name: "",
          parameters: {
            prompt: "Snack chosen",
            options: [
              { id: "a", label: "apple" },
              { id: "b", label: "banana" },
              { id: "c", label: "cherry" },
            ],
          },
          parallelGroup: null,
        },
        {
          id: "br",
          type: "branch",
          name: "",
          parameters: { targets: { a: "apple", b: "banana", c: "cherry" } },
          parallelGroup: null,
        },
      ]),
      step("apple", "Apple", [say("s1", "An apple a day!")], { to: "step", stepId: "bye" }),
      step("banana", "Banana", [say("s2", "Bananas are yellow.")], { to: "step", stepId: "bye" }),
      step(
        "cherry",
        "Cherry",
        [{ id: "p", type: "pause", name: "", parameters: { seconds: 1 }, parallelGroup: null }],
        {
          to: "step",
          stepId: "bye",
        },
      ),
      step("bye", "Goodbye", [say("s3", "Goodbye *friend*!")], { to: "end" }),
      step("never", "Never reached?", []),
    ],
  }),
  conditions: [],
  assignment: { strategy: "fixed", perCondition: 1 },
  questionnaires: [],
};

// A question that waits 10 s for an answer (then "Prompt"), in a step that may last 60 s (then the end).
const timed: MethodsInput = {
  ...rejoining,
  snapshot: snapshotOf({
    id: "exp-4",
    name: "Timed question",
    description: "",
    robotId: "nao6-ros2",
    steps: [
      {
        ...step("ask", "Ask", [
          say("q", "What color was it?"),
          {
            id: "rec",
            type: "record_answer",
            name: "",
            parameters: { options: [{ id: "r", label: "red" }] },
            parallelGroup: null,
            timeLimit: { seconds: 10, after: { to: "step", stepId: "prompt" } },
          },
        ]),
        timeLimit: { seconds: 60, after: { to: "end" } },
      },
      step("bye", "Goodbye", [say("s", "Goodbye.")], { to: "end" }),
      step("prompt", "Prompt", [say("p", "Take your time.")], { to: "end" }),
    ],
  }),
};

describe("the methods text", () => {
  const md = methodsMarkdown(storyteller);
  const plain = methodsPlainText(storyteller);

  it.each<[string, string]>([
    ["the robot and its plugin version", "The robot (NAO6 Robot (ROS2 Integration), plugin 3.0.0)"],
    ["the first step, speech and gesture together", "1. **Introduction.**"],
    [
      "the greeting, quoted exactly, at the same time as the wave",
      "The robot said “Hello. I want to tell you about Kai, an astronaut who went on a mission to Mars.” at the same time as it performed “Open-hand wave”",
    ],
    [
      "the story, word for word",
      "“Kai had been on the Martian surface for six days. On the seventh morning, she walked to the edge of a crater and looked down. Among the grey dust she saw a small rock that was bright red. She picked it up and carried it back to the base.” at the same time as it performed “Look down at the crater”",
    ],
    ["the pause and its length", "There was a pause of 2 seconds. Then the robot said"],
    ["what came after the pause", "Then the robot said “What color was the rock Kai found?” The wizard"],
    [
      "the branch and what resolved it",
      "The wizard recorded the participant's answer to “What did the participant answer?”: “correct (red)” led to “Response — correct”; “incorrect / don't know” led to “Response — incorrect”.",
    ],
    [
      "the correct arm",
      "The robot said “That's right, the rock was red. Thank you for listening!” at the same time as it performed “Nod”. The trial ended here.",
    ],
    [
      "the incorrect arm",
      "“Actually, the rock was red. Thank you for listening!” at the same time as it performed “Head shake”.",
    ],
    ["where the trial ends", "The trial ended here."],
    ["questionnaires before", "Before the trial, participants completed “Background” (4 items)."],
    [
      "questionnaires after, with their instrument",
      "After the trial, participants completed “System Usability Scale (SUS)” (10 items) and “Robot impressions” (24 items, the Godspeed questionnaire).",
    ],
    [
      "conditions and their experiments",
      "The study had 2 conditions: “Expressive” (experiment “Interactive Storyteller”: Gestures with the story) and “Still” (experiment “Still storyteller”).",
    ],
    ["the assignment", "shuffled blocks holding each condition 2 times"],
    ["the version and its hash", `version 3 of “Interactive Storyteller”. The version's SHA-256 hash is \`${HASH}\`.`],
  ])("holds %s", (_fact, text) => {
    expect(md).toContain(text);
  });

  it("names the question a stratified assignment balanced within", () => {
    const stratified = methodsMarkdown({
      ...storyteller,
      assignment: { strategy: "stratified", perCondition: 1, stratifiedBy: "Programming experience" },
    });
    expect(stratified).toContain(
      "HRIStudio assigned participants stratified by Programming experience: within each answer, in shuffled blocks holding each condition once",
    );
  });

  it("says nothing of a step leading to the next one in the list, but names where branch arms lead", () => {
    expect(md).not.toContain("continued to “Story”");
    // Each arm ends the trial itself, so neither says where it continues.
    expect(md.match(/The trial ended here\./g)).toHaveLength(2);
  });

  it("the plain text says the same without Markdown", () => {
    expect(plain).not.toMatch(/\*\*|`|^#/m);
    expect(plain).toContain("1. Introduction. The robot greets the participant with a wave. The robot said “Hello.");
    expect(plain).toContain(`The version's SHA-256 hash is ${HASH}.`);
    expect(plain).toMatch(/^Procedure$/m);
  });

  it.each<[string, string]>([
    ["every answer and its step", "“apple” led to “Apple”; “banana” led to “Banana”; “cherry” led to “Cherry”."],
    ["the answers rejoining", "All three answers then continued to “Goodbye”."],
    ["a pause on its own", "There was a pause of 1 second."],
    [
      "an arm that jumps, named",
      "3. **Banana.** The robot said “Bananas are yellow.” The trial then continued to “Goodbye”.",
    ],
    ["speech escaped for Markdown", "“Goodbye \\*friend\\*!” The trial then ended."],
    ["a step's name ending its own sentence", "6. **Never reached?** The trial then ended."],
    ["no conditions", "The study had no separate conditions: every participant followed this protocol."],
    ["no questionnaires", "No questionnaires were given with the trial."],
  ])("a rejoining branch: %s", (_fact, text) => {
    expect(methodsMarkdown(rejoining)).toContain(text);
  });

  it.each<[string, string]>([
    [
      "a question's time limit and where it led",
      "as one of “red”. If no answer was recorded within 10 seconds, the trial went on to “Prompt”.",
    ],
    ["a step's time limit and where it led", "If the step had not ended within 60 seconds, the trial ended."],
  ])("time limits: %s", (_fact, text) => {
    expect(methodsMarkdown(timed)).toContain(text);
  });

  it("names a sound by its file and hash, and never says a note meant for the wizard", () => {
    const sha256 = "ab12cd34ef56".padEnd(64, "0");
    const sound: MethodsInput = {
      ...storyteller,
      snapshot: snapshotOf({
        id: "exp-3",
        name: "Chime",
        description: "",
        robotId: "nao6-ros2",
        steps: [
          step("s", "Start", [
            {
              id: "p",
              type: "play_audio",
              name: "",
              parameters: { fileId: "f1", name: "chime.wav", sha256 },
              parallelGroup: null,
              note: "Only once the participant is seated.",
            },
          ]),
        ],
      }),
    };
    const md = methodsMarkdown(sound);
    expect(md).toContain(
      `1. **Start.** The sound file “chime.wav” (SHA-256 \`${sha256}\`) was played. The trial then ended.`,
    );
    expect(md).not.toContain("seated");
  });

  it("names each loop in a Loops section: the step's own, and a time limit's, with their bounds", () => {
    const looping: MethodsInput = {
      ...storyteller,
      snapshot: snapshotOf({
        id: "exp-4",
        name: "Ask again",
        description: "",
        robotId: "nao6-ros2",
        steps: [
          {
            ...step("ask", "Ask", [say("q", "What color?")], {
              to: "again",
              stepId: "ask",
              times: 2,
              onward: { to: "next" },
            }),
            timeLimit: { seconds: 10, after: { to: "again", stepId: "ask", times: 1, onward: { to: "end" } } },
          },
          step("bye", "Goodbye", [say("b", "Bye!")]),
        ],
      }),
    };
    const plain = methodsPlainText(looping);
    expect(plain).toContain(
      "Loops\n\nAfter “Ask”, the trial went back to “Ask”, at most 2 times, and then continued to “Goodbye”. When the time limit of 10 seconds in “Ask” ran out, the trial went back to “Ask”, at most once, and then ended.",
    );
    // The step's paragraph leaves where it leads to the Loops section: it goes back first.
    expect(plain).toContain(
      "1. Ask. The robot said “What color?” If the step had not ended within 10 seconds, the trial went back to “Ask”, as the loops below say.\n",
    );
    expect(methodsPlainText(rejoining)).not.toContain("Loops");
  });

  it("keeps the researcher's words unescaped in the plain text", () => {
    expect(methodsPlainText(rejoining)).toContain("“Goodbye *friend*!”");
  });
});

describe("the methods text of a wait for the robot's senses", () => {
  const waiting: MethodsInput = {
    ...storyteller,
    events: [
      {
        id: "head_touched",
        name: "Head touched",
        description: "a touch on the head's front sensor",
        topic: "/touch",
        messageType: "std_msgs/msg/Bool",
        when: { kind: "pressed", field: "data", equals: true },
      },
    ],
    snapshot: snapshotOf({
      id: "exp-3",
      name: "Touch to start",
      description: "",
      robotId: "nao6-ros2",
      steps: [
        step("ask", "Ask", [
          say("q", "Touch my head to start."),
          {
            id: "wait",
            type: "wait_for",
            name: "",
            parameters: {
              events: [
                { id: "t", event: "head_touched", after: { to: "step", stepId: "greet" } },
                { id: "r", event: "heard_ready", after: { to: "end" } },
              ],
            },
            parallelGroup: null,
            timeLimit: { seconds: 20, after: { to: "step", stepId: "prompt" } },
          },
        ]),
        step("prompt", "Prompt", [say("p", "Go on, touch it.")], { to: "end" }),
        step("greet", "Greet", [say("g", "Hello!")], { to: "end" }),
      ],
    }),
  };

  it("names each event awaited with its condition, where it led, the time limit and the wizard's go on", () => {
    expect(methodsPlainText(waiting)).toContain(
      "1. Ask. The robot said “Touch my head to start.” Then the trial waited for the robot to sense “Head touched” (a touch on the head's front sensor; its field data became true, once per press), which led to “Greet”, or “heard_ready”, which ended the trial; if nothing was sensed within 20 seconds, the trial led to “Prompt”. The wizard could also go on without it.",
    );
  });
});
