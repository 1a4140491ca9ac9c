import { describe, expect, it } from "vitest";
import { demographicProblems, type Answers } from "./demographics";
import type { DemographicField } from "./settings";

const fields: DemographicField[] = [
  { key: "age", label: "Age", type: "number", options: [] },
  { key: "handedness", label: "Handedness", type: "choice", options: ["left", "right", "both"] },
  { key: "first_language", label: "First language", type: "text", options: [] },
];

describe("demographic answers", () => {
  it.each<[string, Answers, string[]]>([
    ["all fields answered", { age: 34, handedness: "left", first_language: "Dutch" }, []],
    ["nothing answered (every field is optional)", {}, []],
    ["an age as text", { age: "34" }, ["Age: must be a number"]],
    ["a choice that is not offered", { handedness: "ambidextrous" }, ["Handedness: must be one of left, right, both"]],
    ["a field the study does not define", { name: "Jane Doe" }, ["name: is not a demographic field of this study"]],
    ["overlong text", { first_language: "x".repeat(201) }, ["First language: must be text of at most 200 characters"]],
  ])("%s", (_name, answers, problems) => {
    expect(demographicProblems(fields, answers)).toEqual(problems);
  });
});
