// An action's and a step's properties, rendered by React as the designer
// renders them: the note for the wizard every action has, and the variants per
// condition of an action and of a step.
import { createElement } from "react";
import { renderToStaticMarkup } from "react-dom/server";
import { describe, expect, it } from "vitest";
import { blockFor } from "@/core/designer/blocks";
import type { DesignDraft } from "@/core/designer/types";
import { PropertiesPanel } from "./properties-panel";

const draft: DesignDraft = {
  name: "E",
  description: "",
  robotId: "nao6-ros2",
  steps: [
    {
      id: "s",
      name: "Greeting",
      description: "",
      actions: [
        {
          id: "hi",
          type: "say",
          name: "",
          parameters: { text: "Hello" },
          parallelGroup: null,
          note: "Smile first.",
          variants: { Warm: { parameters: { text: "Hello, friend!" } } },
        },
        { id: "wave", type: "wave", name: "", parameters: {}, parallelGroup: null },
        {
          id: "wait",
          type: "wait_for",
          name: "",
          parameters: { events: [{ id: "e1", event: "head_touched", after: { to: "step", stepId: "s2" } }] },
          parallelGroup: null,
        },
      ],
    },
    { id: "s2", name: "Greet", description: "", actions: [] },
    {
      id: "s3",
      name: "Feedback",
      description: "",
      actions: [
        { id: "praise", type: "say", name: "", parameters: { text: "Well done." }, parallelGroup: null },
        { id: "nod", type: "nod", name: "", parameters: {}, parallelGroup: null },
      ],
      variants: {
        Warm: {
          actions: [
            {
              id: "warm-praise",
              type: "say",
              name: "",
              parameters: { text: "Well done, friend!" },
              parallelGroup: null,
            },
            { id: "warm-sit", type: "posture", name: "", parameters: { posture: "sit" }, parallelGroup: null },
          ],
        },
      },
    },
  ],
};

const render = (id: string, conditions: string[] = [], kind: "action" | "step" = "action") =>
  renderToStaticMarkup(
    createElement(PropertiesPanel, {
      draft,
      selection: { kind, id },
      issues: [],
      blockFor: (type: string) => blockFor(type, null),
      run: () => {},
      onMove: () => {},
      onDelete: () => {},
      studyId: "study",
      robotName: "NAO6",
      audioPlayer: "browser",
      robotEvents: [
        {
          id: "head_touched",
          name: "Head touched",
          topic: "/touch",
          messageType: "std_msgs/msg/Bool",
          when: { kind: "pressed", field: "data", equals: true },
        },
        {
          id: "heard_ready",
          name: "Heard “ready”",
          topic: "/words",
          messageType: "std_msgs/msg/String",
          when: { kind: "pressed", field: "data", equals: true },
        },
      ],
      conditions,
    }),
  );

describe("an action's note for the wizard", () => {
  it("is a field of every action, holding the draft's note", () => {
    const html = render("hi");
    expect(html).toContain("Note for the wizard");
    expect(html).toMatch(/<textarea[^>]*maxLength="2000"[^>]*>Smile first\.<\/textarea>/);
    expect(html).toContain("Not part of the methods text.");
  });

  it("is empty for an action without one", () => {
    expect(render("wave")).toMatch(/<textarea[^>]*maxLength="2000"[^>]*><\/textarea>/);
  });
});

describe("a Wait for's properties", () => {
  it("picks each event from what the robot senses, with where it leads, and offers a time limit", () => {
    const html = render("wait");
    expect(html).toContain("Events the trial waits for");
    expect(html).toMatch(/<option value="head_touched" selected="">Head touched<\/option>/);
    expect(html).toContain("Heard “ready”");
    expect(html).toMatch(/<option value="s2" selected="">Go to step 2: Greet<\/option>/);
    expect(html).toContain("Add an event");
    expect(html).toContain("Nothing sensed in (seconds)");
  });
});

describe("an action that varies by condition", () => {
  it("shows one editor per condition side by side: the variant's own values, or the shared action", () => {
    const html = render("hi", ["Warm", "Plain"]);
    expect(html).toContain("Varies by condition");
    const warm = html.slice(html.indexOf('aria-label="In “Warm”"'), html.indexOf('aria-label="In “Plain”"'));
    expect(warm).toMatch(/<input type="checkbox"[^>]*checked=""/);
    expect(warm).toContain('value="Hello, friend!"');
    const plain = html.slice(html.indexOf('aria-label="In “Plain”"'));
    expect(plain).toContain("Runs the action as above.");
  });

  it("has no such field in a study with no conditions on this experiment", () => {
    expect(render("hi")).not.toContain("Varies by condition");
  });
});

describe("a step that varies by condition", () => {
  it("shows the shared actions beside each condition's own: their text to edit and remove, or the shared ones run", () => {
    const html = render("s3", ["Warm", "Plain"], "step");
    expect(html).toContain("Varies by condition");
    const shared = html.slice(html.indexOf('aria-label="Shared"'), html.indexOf('aria-label="In “Warm”"'));
    expect(shared).toContain("Say: Well done.");
    expect(shared).toContain("Nod");
    const warm = html.slice(html.indexOf('aria-label="In “Warm”"'), html.indexOf('aria-label="In “Plain”"'));
    expect(warm).toMatch(/<input type="checkbox"[^>]*checked=""/);
    expect(warm).toContain("Own actions in “Warm”");
    expect(warm).toMatch(/aria-label="Text of Say: Well done, friend!, action 1 in “Warm”" value="Well done, friend!"/);
    expect(warm).toContain('aria-label="Remove Say: Well done, friend!, action 1 in “Warm”"');
    expect(warm).not.toContain("Nod");
    // Settings beside the main text, folded away: a posture's choice, the say's text only once.
    expect(warm).toContain('aria-label="More settings of Posture: Sit, action 2 in “Warm”"');
    expect(warm).toMatch(/<option selected="">sit<\/option>/);
    expect(warm).not.toContain("More settings of Say");
    const plain = html.slice(html.indexOf('aria-label="In “Plain”"'));
    expect(plain).not.toMatch(/<input type="checkbox"[^>]*checked=""/);
    expect(plain).toContain("Runs the step&#x27;s actions.");
  });
});
