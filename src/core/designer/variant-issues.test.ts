import { describe, expect, it } from "vitest";
import type { DesignDraft } from "./types";
import { variantIssues } from "./variant-issues";

const draft: DesignDraft = {
  name: "Tutor",
  description: "",
  robotId: "nao6-ros2",
  steps: [
    {
      id: "s1",
      name: "Feedback",
      description: "",
      actions: [
        {
          id: "a1",
          type: "say",
          name: "",
          parameters: { text: "Well done." },
          parallelGroup: null,
          variants: { Warm: { parameters: { text: "Well done, friend!" } } },
        },
      ],
    },
  ],
};

describe("what the designer says of a design's variants", () => {
  it.each<[string[], Array<[string, string, string | undefined]>]>([
    [["Warm"], []],
    [["Warm", "Plain"], [["warning", "variant_missing", "a1"]]],
    [
      ["Plain"],
      [
        ["warning", "variant_missing", "a1"],
        ["error", "variant_unknown_condition", undefined],
      ],
    ],
    // A study with no conditions on this experiment: nothing lacks, but the variant is for no condition.
    [[], [["error", "variant_unknown_condition", undefined]]],
  ])("with the conditions %j", (conditions, expected) => {
    expect(variantIssues(draft, conditions).map((i) => [i.severity, i.code, i.actionId])).toEqual(expected);
  });

  it("names the conditions that lack a variant, and the ones no condition is named", () => {
    expect(variantIssues(draft, ["Plain"]).map((i) => i.message)).toEqual([
      'This action varies by condition, but "Plain" has no variant of it and runs the shared one.',
      'Variants for "Warm": no condition of this study by that name runs this experiment. Remove them, or rename the condition they were for back to that name.',
    ]);
  });
});
