import { describe, expect, it } from "vitest";
import { ANSWER_COLUMNS } from "@/core/questionnaires/export";
import { CODE_COLUMNS } from "@/core/coding/export";
import { codebookCsv } from "./codebook";
import { EVENT_COLUMNS, SAMPLE_COLUMNS } from "./exports";

const rows = codebookCsv()
  .trimEnd()
  .split("\r\n")
  .map((line) => line.split(","));

describe("the study zip's codebook", () => {
  it.each([
    ["trials/<id>-events.csv", EVENT_COLUMNS],
    ["trials/<id>-samples.csv", SAMPLE_COLUMNS],
    ["codes.csv", CODE_COLUMNS],
    ["questionnaire-answers.csv", ANSWER_COLUMNS],
  ])("names every column of %s, in its order", (file, columns) => {
    expect(rows.filter((r) => r[0] === file).map((r) => r[1])).toEqual([...columns]);
  });

  it.each([
    ["rel_ms", "trials/<id>-samples.csv", ["integer", "ms", "", "false"]],
    ["kind", "codes.csv", ["text", "", "point; state", "false"]],
    ["reverse_scored", "questionnaire-answers.csv", ["boolean", "", "", "true"]],
    ["measure", "questionnaire-answers.csv", ["text", "", "answer; score", "false"]],
  ])("gives %s of %s its type, unit, allowed values and whether it may be empty", (variable, file, described) => {
    expect(rows.find((r) => r[0] === file && r[1] === variable)!.slice(2, 6)).toEqual(described);
  });
});
