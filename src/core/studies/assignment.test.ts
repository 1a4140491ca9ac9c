import { describe, expect, it } from "vitest";
import { assign, balancedLatinSquare, type Strategy } from "./assignment";

const conditions = ["NAO with gestures", "TurtleBot voice only"];
const conditionOf = (strategy: Strategy, seed: string, n: number, list = conditions) =>
  Array.from({ length: n }, (_, i) => (assign(strategy, list, seed, i) as { condition: string }).condition);
const counts = (xs: string[]) => xs.reduce<Record<string, number>>((c, x) => ({ ...c, [x]: (c[x] ?? 0) + 1 }), {});

describe("assigning conditions", () => {
  it.each<[string, Strategy]>([
    ["random", { kind: "random" }],
    ["balanced", { kind: "balanced", perCondition: 2 }],
    ["counterbalanced", { kind: "counterbalanced" }],
  ])("%s: the same seed gives the same assignments, another seed others", (_name, strategy) => {
    const run = (seed: string) =>
      Array.from({ length: 40 }, (_, i) => JSON.stringify(assign(strategy, ["A", "B", "C"], seed, i)));
    expect(run("study-42")).toEqual(run("study-42"));
    if (strategy.kind !== "counterbalanced") expect(run("study-42")).not.toEqual(run("study-43"));
  });

  it.each([1, 2, 3])("balanced with %i per condition: counts never differ by more than one block", (perCondition) => {
    const three = ["A", "B", "C"];
    for (let n = 1; n <= 60; n++) {
      const c = counts(conditionOf({ kind: "balanced", perCondition }, "seed", n, three));
      const values = three.map((x) => c[x] ?? 0);
      expect(Math.max(...values) - Math.min(...values)).toBeLessThanOrEqual(perCondition);
    }
    const full = counts(conditionOf({ kind: "balanced", perCondition }, "seed", 3 * perCondition * 4, three));
    expect(Object.values(full)).toEqual([4 * perCondition, 4 * perCondition, 4 * perCondition]);
  });

  it("random uses every condition over many participants", () => {
    const c = counts(conditionOf({ kind: "random" }, "seed", 200));
    expect(Object.keys(c).sort()).toEqual([...conditions].sort());
  });

  it("fixed takes the researcher's choice and refuses anything else", () => {
    expect(assign({ kind: "fixed" }, conditions, "s", 0, "TurtleBot voice only")).toEqual({
      condition: "TurtleBot voice only",
    });
    expect(() => assign({ kind: "fixed" }, conditions, "s", 0, "Pepper")).toThrow(
      "Choose one of the conditions: NAO with gestures, TurtleBot voice only.",
    );
  });

  it.each([2, 3, 4, 5, 6])(
    "a balanced Latin square of %i: every condition once per position, and carry-over balanced",
    (n) => {
      const rows = balancedLatinSquare(n);
      expect(rows).toHaveLength(n % 2 === 0 ? n : 2 * n);
      for (const row of rows) expect([...row].sort((a, b) => a - b)).toEqual(Array.from({ length: n }, (_, i) => i));
      for (let p = 0; p < n; p++) {
        const column = counts(rows.map((r) => String(r[p])));
        expect(new Set(Object.values(column)).size).toBe(1);
      }
      // Every ordered pair (a right before b) occurs equally often.
      const pairs = counts(rows.flatMap((r) => r.slice(1).map((b, i) => `${r[i]}>${b}`)));
      expect(Object.keys(pairs)).toHaveLength(n * (n - 1));
      expect(new Set(Object.values(pairs)).size).toBe(1);
    },
  );

  it("refuses a study without conditions and a negative position", () => {
    expect(() => assign({ kind: "random" }, [], "s", 0)).toThrow("The study has no conditions to assign.");
    expect(() => assign({ kind: "random" }, conditions, "s", -1)).toThrow("position must be a whole number from 0.");
  });
});
