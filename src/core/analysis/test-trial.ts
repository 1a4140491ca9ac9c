// A small protocol with a parallel group, a question, a branch and two endings,
// and the commands of a perfect run of it: shared by the analysis tests.
import type { Command, TrialProtocol } from "../trial";

export const protocol: TrialProtocol = {
  steps: [
    {
      id: "intro",
      name: "Introduction",
      actions: [
        { id: "hello", type: "say", parameters: { text: "Hello" }, parallelGroup: "g" },
        { id: "wave", type: "wave", parameters: {}, parallelGroup: "g" },
      ],
    },
    {
      id: "ask",
      name: "Question",
      actions: [
        { id: "q", type: "say", parameters: { text: "Colour?" } },
        {
          id: "answer",
          type: "record_answer",
          parameters: {
            options: [
              { id: "yes", label: "red" },
              { id: "no", label: "other" },
            ],
          },
        },
        { id: "branch", type: "branch", parameters: { targets: { yes: "right", no: "wrong" } } },
      ],
    },
    {
      id: "right",
      name: "Right",
      actions: [
        { id: "nod", type: "nod", parameters: {} },
        { id: "end-r", type: "end_trial", parameters: {} },
      ],
    },
    {
      id: "wrong",
      name: "Wrong",
      actions: [
        { id: "shake", type: "head_shake", parameters: {} },
        { id: "end-w", type: "end_trial", parameters: {} },
      ],
    },
  ],
};

export const done = (...ids: string[]): Command[] =>
  ids.flatMap(
    (actionId) =>
      [
        { kind: "dispatched", actionId },
        { kind: "completed", actionId },
      ] as Command[],
  );
export const perfect: Command[] = [
  { kind: "start" },
  { kind: "next" },
  ...done("hello", "wave"),
  { kind: "next" },
  { kind: "next" },
  ...done("q"),
  { kind: "answer", actionId: "answer", optionId: "yes" },
  { kind: "next" },
  ...done("nod"),
  { kind: "next" },
];
