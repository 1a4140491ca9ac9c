import { describe, expect, it } from "vitest";
import { actionCountProblem, draftSchema } from "./document";

const steps = (count: number, actions: number) =>
  Array.from({ length: count }, (_, i) => ({
    id: `s${i}`,
    name: `Step ${i + 1}`,
    actions: Array.from({ length: actions }, (_, a) => ({ id: `s${i}a${a}`, type: "wave" })),
  }));

describe("the size of a design", () => {
  it.each<[string, unknown[], string | null]>([
    ["no steps", [], null],
    ["exactly the limit", steps(100, 500), null],
    ["one action over", [...steps(100, 500), ...steps(1, 1)], "The design has 50,001 actions; the limit is 50,000."],
    ["steps that are not objects, counted as holding nothing", [null, 3, "x", { actions: "no" }], null],
  ])("%s", (_name, given, problem) => {
    expect(actionCountProblem(given)).toBe(problem);
  });

  it.each<[string, unknown, string]>([
    ["too many actions in all", steps(101, 500), "The design has 50,500 actions; the limit is 50,000."],
    ["too many steps", steps(501, 0), "An experiment can hold at most 500 steps"],
  ])("refuses %s before reading any step, the limit named", (_name, given, message) => {
    // Every step is also invalid (its name is empty): only the count is reported.
    const bad = (given as Array<{ actions: unknown[] }>).map((s) => ({ ...s, name: "", actions: s.actions }));
    const result = draftSchema.safeParse({ name: "E", robotId: "nao6-ros2", steps: bad });
    expect(result.success).toBe(false);
    expect(result.error!.issues.map((i) => [i.path.join("."), i.message])).toEqual([["steps", message]]);
  });
});
