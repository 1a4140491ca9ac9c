// The Interactive Storyteller (the project brief's protocol document,
// interactive-storyteller.md, which nothing here reads), the demo experiment. Speech is the protocol's exact text.
import type { DesignDraft } from "@/core/designer/types";

export interface SeedAction {
  type: string;
  name: string;
  parameters: Record<string, unknown>;
  parallelGroup?: string;
}

export interface SeedStep {
  key: string;
  name: string;
  description: string;
  actions: SeedAction[];
}

export const STORYTELLER = {
  name: "Interactive Storyteller",
  description:
    "Does the way a robot tells a story change what a listener remembers? The robot tells a short story about Kai on Mars, asks a recall question, and responds to the answer.",
  robotId: "nao6-ros2",
};

// Branch targets name steps by key; the seed swaps keys for the stored step ids.
export const STORYTELLER_STEPS: SeedStep[] = [
  {
    key: "introduction",
    name: "Introduction",
    description: "The robot greets the participant with a wave.",
    actions: [
      {
        type: "say",
        name: "Greeting",
        parameters: { text: "Hello. I want to tell you about Kai, an astronaut who went on a mission to Mars." },
        parallelGroup: "intro",
      },
      { type: "wave", name: "Open-hand wave", parameters: {}, parallelGroup: "intro" },
    ],
  },
  {
    key: "story",
    name: "Story",
    description: "The robot tells the story and looks down at the crater.",
    actions: [
      {
        type: "say",
        name: "Story",
        parameters: {
          text: "Kai had been on the Martian surface for six days. On the seventh morning, she walked to the edge of a crater and looked down. Among the grey dust she saw a small rock that was bright red. She picked it up and carried it back to the base.",
        },
        parallelGroup: "story",
      },
      { type: "look_down", name: "Look down at the crater", parameters: {}, parallelGroup: "story" },
    ],
  },
  {
    key: "recall",
    name: "Recall question",
    description: "The robot pauses, asks about the rock, and the wizard records the answer.",
    actions: [
      { type: "pause", name: "Hold still", parameters: { seconds: 2 } },
      { type: "say", name: "Question", parameters: { text: "What color was the rock Kai found?" } },
      {
        type: "record_answer",
        name: "Participant's answer",
        parameters: {
          prompt: "What did the participant answer?",
          options: [
            { id: "correct", label: "correct (red)" },
            { id: "incorrect", label: "incorrect / don't know" },
          ],
        },
      },
      {
        type: "branch",
        name: "Respond to the answer",
        parameters: { targets: { correct: "@response-correct", incorrect: "@response-incorrect" } },
      },
    ],
  },
  {
    key: "response-correct",
    name: "Response — correct",
    description: "Branch A: the participant remembered the red rock.",
    actions: [
      {
        type: "say",
        name: "Confirm",
        parameters: { text: "That's right, the rock was red. Thank you for listening!" },
        parallelGroup: "confirm",
      },
      { type: "nod", name: "Nod", parameters: {}, parallelGroup: "confirm" },
      { type: "end_trial", name: "End", parameters: {} },
    ],
  },
  {
    key: "response-incorrect",
    name: "Response — incorrect",
    description: "Branch B: the participant did not remember.",
    actions: [
      {
        type: "say",
        name: "Correct the answer",
        parameters: { text: "Actually, the rock was red. Thank you for listening!" },
        parallelGroup: "correct",
      },
      { type: "head_shake", name: "Head shake", parameters: {}, parallelGroup: "correct" },
      { type: "end_trial", name: "End", parameters: {} },
    ],
  },
];

/**
 * The Storyteller as a design draft: step and action ids from `idFor` (given
 * the step key, or "<key>-<n>" for an action), branch targets resolved from
 * "@key" to the target step's id. The seed and the tests build it here.
 */
export function storytellerDraft(idFor: (key: string) => string = (key) => key): DesignDraft {
  const stepIds = new Map(STORYTELLER_STEPS.map((s) => [s.key, idFor(s.key)]));
  const resolve = (value: Record<string, unknown>) =>
    JSON.parse(
      JSON.stringify(value, (_k, v) =>
        typeof v === "string" && v.startsWith("@") && stepIds.has(v.slice(1)) ? stepIds.get(v.slice(1)) : v,
      ),
    ) as Record<string, unknown>;
  return {
    ...STORYTELLER,
    steps: STORYTELLER_STEPS.map((s) => ({
      id: stepIds.get(s.key)!,
      name: s.name,
      description: s.description,
      actions: s.actions.map((a, i) => ({
        id: idFor(`${s.key}-${i}`),
        type: a.type,
        name: a.name,
        parameters: resolve(a.parameters),
        parallelGroup: a.parallelGroup ?? null,
      })),
    })),
  };
}
