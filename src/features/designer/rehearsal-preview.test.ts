// The rehearsal preview rendered by React as the designer renders it: with
// conditions on the experiment it may walk the draft as one of them.
import { createElement } from "react";
import { renderToStaticMarkup } from "react-dom/server";
import { describe, expect, it } from "vitest";
import type { DesignDraft } from "@/core/designer/types";
import { RehearsalPreview } from "./rehearsal-preview";

const draft: DesignDraft = {
  name: "Tutor",
  description: "",
  robotId: "nao6-ros2",
  steps: [
    {
      id: "s",
      name: "Feedback",
      description: "",
      actions: [
        {
          id: "a",
          type: "say",
          name: "Praise",
          parameters: { text: "Well done." },
          parallelGroup: null,
          variants: { Warm: { parameters: { text: "Well done, friend!" } } },
        },
      ],
    },
  ],
};

const render = (conditions: string[]) =>
  renderToStaticMarkup(
    createElement(RehearsalPreview, {
      draft,
      actionName: (a) => a.name,
      eventName: (id) => id,
      blocked: null,
      conditions,
    }),
  );

describe("the rehearsal preview of an experiment whose conditions vary", () => {
  it("offers each condition, and walks the shared design until one is chosen", () => {
    const html = render(["Warm", "Plain"]);
    expect(html).toContain("As condition");
    expect(html.match(/<option [^>]*>[^<]*<\/option>/g)).toEqual([
      '<option value="" selected="">The shared design (no condition&#x27;s variants)</option>',
      '<option value="Warm">Warm</option>',
      '<option value="Plain">Plain</option>',
    ]);
    expect(html).toContain("“Well done.”");
  });

  it("has no choice of condition where none runs the experiment", () => {
    expect(render([])).not.toContain("As condition");
  });
});
