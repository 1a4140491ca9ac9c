// JSON as rosbridge's Python reads and writes it: NaN and Infinity literals.
import { describe, expect, it } from "vitest";
import { parsePythonJson } from "./python-json";

describe("Python's JSON", () => {
  it.each<[string, string, unknown]>([
    ["plain JSON", '{"a":1.5,"b":"x"}', { a: 1.5, b: "x" }],
    ["NaN", '{"t":NaN}', { t: Number.NaN }],
    [
      "Infinity and -Infinity in a list",
      "[Infinity,-Infinity,1.0]",
      [Number.POSITIVE_INFINITY, Number.NEGATIVE_INFINITY, 1],
    ],
    [
      "the words inside a string stay text",
      '{"data":"NaN and -Infinity \\" NaN"}',
      { data: 'NaN and -Infinity " NaN' },
    ],
  ])("%s", (_, text, value) => {
    expect(parsePythonJson(text)).toEqual(value);
  });

  it("still refuses what is not JSON", () => {
    expect(() => parsePythonJson("{nan}")).toThrow();
  });
});
