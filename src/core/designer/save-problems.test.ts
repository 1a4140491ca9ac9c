import { describe, expect, it } from "vitest";
import { z } from "zod";
import { describeSaveIssues } from "./save-problems";
import type { DesignDraft } from "./types";

const draft: DesignDraft = {
  name: "Quiz",
  description: "",
  robotId: "nao6-ros2",
  steps: [
    { id: "s1", name: "Welcome", description: "", actions: [] },
    {
      id: "s2",
      name: "Question",
      description: "",
      actions: [
        { id: "a1", type: "say", name: "", parameters: {}, parallelGroup: null },
        { id: "a2", type: "nao6-ros2.play_animation_bow", name: "", parameters: {}, parallelGroup: null },
        { id: "a3", type: "record_answer", name: "Favourite planet", parameters: {}, parallelGroup: null },
      ],
    },
  ],
};

// Zod's own wording for limits nobody wrote a message for, as this version of zod says it.
const zodSays = (schema: z.ZodType, value: unknown) => schema.safeParse(value).error!.issues[0]!.message;

describe("a refused save, said about its step and action", () => {
  it.each([
    [
      "steps.1.actions.2.name",
      "must be at most 200 characters",
      'Step 2 "Question", action 3 "Favourite planet": Label must be at most 200 characters.',
    ],
    [
      "steps.1.actions.0.parameters",
      "must be smaller than 64 KB",
      'Step 2 "Question", action 1 "Say": Settings must be smaller than 64 KB.',
    ],
    [
      "steps.1.actions.1.type",
      "Action type must not be empty",
      'Step 2 "Question", action 2 "play_animation_bow": Action type must not be empty.',
    ],
    ["steps.0.name", "Step name must not be empty", 'Step 1 "Welcome": Step name must not be empty.'],
    [
      "steps.0.description",
      "must be at most 5000 characters",
      'Step 1 "Welcome": Description must be at most 5000 characters.',
    ],
    ["details.description", "must be at most 5000 characters", "Description must be at most 5000 characters."],
    ["steps", zodSays(z.array(z.number()).max(500), Array(501).fill(0)), "The experiment can have at most 500 steps."],
    [
      "steps.1.actions",
      zodSays(z.array(z.number()).max(500), Array(501).fill(0)),
      'Step 2 "Question": The step can have at most 500 actions.',
    ],
    [
      "steps.1.actions.0.parallelGroup",
      zodSays(z.string().min(1), ""),
      'Step 2 "Question", action 1 "Say": Run together must not be empty.',
    ],
  ])("%s: %s", (field, message, expected) => {
    const said = describeSaveIssues(draft, [{ field, message }]);
    expect(said).toBe(expected);
    expect(said).not.toMatch(/steps\.\d|Too big|Too small|<=|>=/);
  });
});
