// The note for the wizard in an action's properties, rendered by React as the
// designer renders it: every action has one, holding what the draft holds.
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
        { id: "hi", type: "say", name: "", parameters: { text: "Hello" }, parallelGroup: null, note: "Smile first." },
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
  ],
};

const render = (actionId: string) =>
  renderToStaticMarkup(
    createElement(PropertiesPanel, {
      draft,
      selection: { kind: "action", id: actionId },
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
