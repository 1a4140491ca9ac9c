import { describe, expect, it } from "vitest";
import { loadOrder, type Reference } from "./table-order";

const ref = (from: string, to: string): Reference => ({ from, to });

describe("loadOrder", () => {
  it.each<[string, string[], Reference[], string[]]>([
    ["no references: alphabetical", ["b", "a", "c"], [], ["a", "b", "c"]],
    ["a child after its parent", ["trials", "studies"], [ref("trials", "studies")], ["studies", "trials"]],
    [
      "a chain",
      ["events", "trials", "studies"],
      [ref("events", "trials"), ref("trials", "studies")],
      ["studies", "trials", "events"],
    ],
    [
      "two parents",
      ["trials", "user", "studies"],
      [ref("trials", "studies"), ref("trials", "user"), ref("studies", "user")],
      ["user", "studies", "trials"],
    ],
    [
      "a table pointing at itself",
      ["steps", "experiments"],
      [ref("steps", "steps"), ref("steps", "experiments")],
      ["experiments", "steps"],
    ],
    ["a reference to a table outside the list is ignored", ["a"], [ref("a", "elsewhere")], ["a"]],
    ["the same reference twice", ["a", "b"], [ref("b", "a"), ref("b", "a")], ["a", "b"]],
  ])("%s", (_, tables, references, expected) => {
    expect(loadOrder(tables, references)).toEqual(expected);
  });

  it("refuses a circle, naming the tables in it", () => {
    expect(() => loadOrder(["a", "b", "c"], [ref("a", "b"), ref("b", "a")])).toThrow(
      "The tables a, b point at each other in a circle",
    );
  });
});
