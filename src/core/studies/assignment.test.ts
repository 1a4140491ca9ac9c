import { describe, expect, it } from "vitest";
import {
  assign,
  balancedLatinSquare,
  NOT_GIVEN,
  type Strategy,
  strataCounts,
  strategyFor,
  stratumOf,
} from "./assignment";

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

  it("stratified: each stratum is balanced on its own, whatever order the strata arrive in", () => {
    const three = ["A", "B", "C"];
    // Experience of 60 participants in an uneven, interleaved order.
    const arrivals = Array.from({ length: 60 }, (_, i) => (i % 5 === 0 ? "none" : i % 2 ? "some" : "a lot"));
    const seen: Record<string, number> = {};
    const given = arrivals.map((stratum) => {
      const position = seen[stratum] ?? 0;
      seen[stratum] = position + 1;
      const strategy: Strategy = { kind: "stratified", perCondition: 1, stratum };
      return { stratum, condition: (assign(strategy, three, "seed", position) as { condition: string }).condition };
    });
    for (const { stratum, counts: c } of strataCounts(given)) {
      const values = three.map((x) => c[x] ?? 0);
      expect(Math.max(...values) - Math.min(...values), stratum).toBeLessThanOrEqual(1);
      expect(values.reduce((a, b) => a + b)).toBe(seen[stratum]);
    }
  });

  it("stratified: strata draw from their own shuffles, reproducibly", () => {
    const run = (stratum: string) =>
      Array.from({ length: 12 }, (_, i) =>
        JSON.stringify(assign({ kind: "stratified", perCondition: 1, stratum }, ["A", "B", "C"], "seed", i)),
      );
    expect(run("none")).toEqual(run("none"));
    expect(run("none")).not.toEqual(run("a lot"));
  });

  it.each<[string, Record<string, unknown>, string]>([
    ["the answer", { experience: "some" }, "some"],
    ["a number as text", { experience: 3 }, "3"],
    ["no answer", {}, NOT_GIVEN],
    ["an empty answer", { experience: "" }, NOT_GIVEN],
  ])("a participant's stratum: %s", (_, demographics, stratum) => {
    expect(stratumOf("experience", demographics)).toBe(stratum);
  });

  it.each<[string, Parameters<typeof strategyFor>[0], Strategy]>([
    ["fixed", { strategy: "fixed", perCondition: 1 }, { kind: "fixed" }],
    ["balanced", { strategy: "balanced", perCondition: 2 }, { kind: "balanced", perCondition: 2 }],
    [
      "stratified",
      { strategy: "stratified", perCondition: 2, stratifyBy: "experience" },
      { kind: "stratified", perCondition: 2, stratum: "some" },
    ],
  ])("the strategy settings give a participant: %s", (_, settings, strategy) => {
    expect(strategyFor(settings, { experience: "some" })).toEqual(strategy);
  });
});
