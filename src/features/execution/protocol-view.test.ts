// What the wizard reads for each action, rendered by React as the trial page
// renders it: a name for every action, a pause with its length.
import { createElement } from "react";
import { renderToStaticMarkup } from "react-dom/server";
import { describe, expect, it } from "vitest";
import { actionNamesOf } from "@/core/designer/action-name";
import { fold, type TrialProtocol } from "@/core/trial";
import { OffScript, StepActions } from "./protocol-view";
import { nextLabel } from "./wizard-controls";

const protocol: TrialProtocol = {
  steps: [
    {
      id: "s",
      name: "Welcome",
      actions: [
        { id: "hold", type: "pause", name: "Hold still", parameters: { seconds: 2 } },
        { id: "pause", type: "pause", name: "", parameters: { seconds: 3 } },
        { id: "hi", type: "say", name: "", parameters: { text: "Hi! I am Nao, and today I will tell you a story." } },
        { id: "bow", type: "nao6-ros2.play_animation_bow", parameters: {} },
      ],
    },
  ],
};
const names = actionNamesOf(null);
const state = fold(protocol, [
  { type: "trial.started", seq: 1, relMs: 0 },
  { type: "step.entered", stepId: "s", via: "start", seq: 2, relMs: 0 },
]);
const text = (html: string) => html.replace(/<[^>]+>/g, " ").replace(/\s+/g, " ");

describe("the wizard's view of the current step", () => {
  const shown = text(renderToStaticMarkup(createElement(StepActions, { protocol, names, state, problems: {} })));

  it.each([
    ["a labelled pause, with its length", "Hold still 2 s"],
    ["an unlabelled pause, by its length", "Pause 3 s"],
    ["unlabelled speech, by its text", "Say: Hi! I am Nao, and today I will…"],
    ["a robot's own action without its plugin, in words", "Play animation bow"],
  ])("shows %s", (_, expected) => {
    expect(shown).toContain(expected);
  });

  it("names the next action on the big button, and an off-script one by its block", () => {
    expect(nextLabel(protocol, state, names)).toBe("Hold still");
    const off = renderToStaticMarkup(
      createElement(OffScript, {
        events: [{ type: "action.requested", actionId: "u1", actionType: "nod", scripted: false, parameters: {} }],
        names,
        state,
        problems: {},
      }),
    );
    expect(text(off)).toContain(" Nod ");
  });
});

describe("the big button, once a step's actions are done", () => {
  const step = (id: string, after?: TrialProtocol["steps"][number]["after"]) => ({
    id,
    name: id,
    actions: [],
    ...(after ? { after } : {}),
  });
  const at = (p: TrialProtocol, stepId: string) =>
    fold(p, [
      { type: "trial.started", seq: 1, relMs: 0 },
      { type: "step.entered", stepId, via: "start", seq: 2, relMs: 0 },
    ]);

  it.each<[string, TrialProtocol, string]>([
    ["the next step in the list", { steps: [step("Mars"), step("Venus")] }, "Go to “Venus”"],
    [
      "the step where the answers meet, not the sibling below",
      { steps: [step("Mars", { to: "step", stepId: "Goodbye" }), step("Venus"), step("Goodbye")] },
      "Go to “Goodbye”",
    ],
    ["the end, when the step leads there", { steps: [step("Mars", { to: "end" }), step("Venus")] }, "Finish trial"],
  ])("names %s", (_name, p, expected) => {
    expect(nextLabel(p, at(p, "Mars"), names)).toBe(expected);
  });
});
