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
      ],
    },
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
