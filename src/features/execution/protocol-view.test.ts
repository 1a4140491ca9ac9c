// What the wizard reads for each action, rendered by React as the trial page
// renders it: a name for every action, a pause with its length.
import { createElement } from "react";
import { renderToStaticMarkup } from "react-dom/server";
import { describe, expect, it } from "vitest";
import { actionNamesOf } from "@/core/designer/action-name";
import { fold, type TrialProtocol } from "@/core/trial";
import { OffScript, StepActions } from "./protocol-view";
import { browserSounds } from "./browser-sounds";
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

describe("what the wizard reads beside the actions", () => {
  const guided: TrialProtocol = {
    steps: [
      {
        id: "g",
        name: "Greeting",
        description: "The participant sits down.\nWait for eye contact.",
        actions: [
          { id: "hi", type: "say", parameters: { text: "Hello" }, note: "Warmly; repeat once if unheard." },
          { id: "chime", type: "play_audio", parameters: { fileId: "f1", name: "chime.wav", sha256: "a".repeat(64) } },
        ],
      },
    ],
  };
  const at = fold(guided, [
    { type: "trial.started", seq: 1, relMs: 0 },
    { type: "step.entered", stepId: "g", via: "start", seq: 2, relMs: 0 },
  ]);
  const render = (notes: boolean) =>
    renderToStaticMarkup(createElement(StepActions, { protocol: guided, names, state: at, problems: {}, notes }));

  it("the step's description, with its line breaks, under its name", () => {
    expect(render(true)).toContain(
      '<p class="mt-1 max-w-prose whitespace-pre-line text-slate-700" data-testid="step-description">The participant sits down.\nWait for eye contact.</p>',
    );
  });

  it("each action's note, announced as the wizard's, under that action only", () => {
    const html = render(true);
    expect(text(html)).toContain("Say: Hello Note for the wizard: Warmly; repeat once if unheard.");
    expect(html.match(/data-testid="action-note"/g)).toHaveLength(1);
    expect(text(html)).toContain("Play audio: chime.wav");
  });

  it("observers see the description but not the notes meant for the wizard", () => {
    const html = render(false);
    expect(html).toContain('data-testid="step-description"');
    expect(html).not.toContain("Warmly");
  });
});

describe("the sounds the wizard's browser plays", () => {
  const p: TrialProtocol = {
    steps: [
      {
        id: "s",
        name: "S",
        actions: [
          { id: "a", type: "play_audio", parameters: { fileId: "f1", name: "one.wav" } },
          { id: "b", type: "play_audio", parameters: { fileId: "f2", name: "two.wav" } },
        ],
      },
    ],
  };
  const log = [
    { type: "trial.started", seq: 1, relMs: 0 },
    { type: "step.entered", stepId: "s", via: "start", seq: 2, relMs: 0 },
    {
      type: "action.requested",
      stepId: "s",
      actionId: "a",
      actionType: "play_audio",
      parameters: { fileId: "f1", name: "one.wav" },
      scripted: true,
      seq: 3,
      relMs: 1,
    },
    { type: "action.dispatched", actionId: "a", detail: { playedBy: "browser" }, seq: 4, relMs: 1 },
    {
      type: "action.requested",
      stepId: "s",
      actionId: "b",
      actionType: "play_audio",
      parameters: { fileId: "f2", name: "two.wav" },
      scripted: true,
      seq: 5,
      relMs: 2,
    },
    { type: "action.dispatched", actionId: "b", detail: { robotAction: "play_audio" }, seq: 6, relMs: 2 },
  ] as const;
  const sounds = (events: readonly Record<string, unknown>[]) =>
    browserSounds(events as never, fold(p, events as never));

  it.each<[string, readonly Record<string, unknown>[], string[]]>([
    ["one handed to the browser, not one the robot plays", log, ["a:f1:one.wav:playing"]],
    [
      "one the emergency stop silenced, until its end is logged",
      [...log, { type: "trial.emergency_stop", seq: 7, relMs: 3 }],
      ["a:f1:one.wav:silenced"],
    ],
    ["none once it has ended", [...log, { type: "action.completed", actionId: "a", seq: 7, relMs: 3 }], []],
    ["none once it failed", [...log, { type: "action.failed", actionId: "a", reason: "x", seq: 7, relMs: 3 }], []],
    ["none before it is handed over", log.slice(0, 3), []],
  ])("%s", (_, events, expected) => {
    expect(
      sounds(events).map((s) => `${s.actionId}:${s.fileId}:${s.name}:${s.silenced ? "silenced" : "playing"}`),
    ).toEqual(expected);
  });
});
