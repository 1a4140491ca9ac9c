import { describe, expect, it } from "vitest";
import { namedIn, nulPath } from "./input";

const KEYS = new Set(["trialId", "stepIds"]);

describe("namedIn", () => {
  it.each([
    ["nothing", {}, []],
    ["a top-level id", { trialId: "t1" }, [{ path: "trialId", key: "trialId", value: "t1" }]],
    ["a nested id", { a: [{ trialId: "t2" }] }, [{ path: "a.0.trialId", key: "trialId", value: "t2" }]],
    ["an id array", { stepIds: ["s1"] }, [{ path: "stepIds", key: "stepIds", value: ["s1"] }]],
    [
      "a non-string value, kept for the caller to refuse",
      { trialId: 5 },
      [{ path: "trialId", key: "trialId", value: 5 }],
    ],
    ["not an object", "trialId", []],
  ])("%s", (_name, input, expected) => {
    expect(namedIn(input, KEYS)).toEqual(expected);
  });
});

describe("nulPath", () => {
  it.each([
    ["clean text", { text: "hello" }, null],
    ["a NUL in a value", { steps: [{ name: "a\u0000b" }] }, "steps.0.name"],
    ["a NUL in a key", { ["x\u0000"]: 1 }, "x\\0"],
    ["a NUL in a bare string", "a\u0000", "(input)"],
    ["numbers only", { n: 1, m: [2, 3] }, null],
  ])("%s", (_name, input, expected) => {
    expect(nulPath(input)).toBe(expected);
  });
});
