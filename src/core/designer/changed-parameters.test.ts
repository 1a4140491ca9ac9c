import { describe, expect, it } from "vitest";
import { changedParameters } from "./changed-parameters";

describe("the parameters a settings form changed", () => {
  it.each([
    ["one value edited", { text: "Hi", posture: "sit" }, { text: "Hi", posture: "stand" }, [["posture", "stand"]]],
    ["a value added", { text: "Hi" }, { text: "Hi", seconds: 3 }, [["seconds", 3]]],
    ["a value cleared", { seconds: 3 }, { seconds: undefined }, [["seconds", undefined]]],
    ["nothing edited", { text: "Hi", loud: false }, { text: "Hi", loud: false }, []],
    ["false from nothing", {}, { loud: false }, [["loud", false]]],
  ])("%s", (_, before, after, changed) => {
    expect(changedParameters(before, after)).toEqual(changed);
  });
});
