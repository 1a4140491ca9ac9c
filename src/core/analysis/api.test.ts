import { describe, expect, it } from "vitest";
import { chooseFormat, pathParameters } from "./api";
import { tableCsv, tableJson, tableOf } from "./table";

describe("the format of an answer", () => {
  it.each([
    [null, null, "csv"],
    [null, "*/*", "csv"],
    [null, "application/json", "json"],
    [null, "text/csv, application/json", "csv"],
    ["json", "text/csv", "json"],
    ["csv", "application/json", "csv"],
    ["xlsx", null, { error: "Please correct: format: must be csv or json (not “xlsx”)" }],
    ["", null, { error: "Please correct: format: must be csv or json (not “”)" }],
  ])("?format=%j, Accept %j → %j", (format, accept, chosen) => {
    expect(chooseFormat(format, accept)).toEqual(chosen);
  });
});

describe("a tidy table", () => {
  const table = tableOf(["trial_id", "seq", "note", "ended"] as const, [
    { trial_id: "t1", seq: 1, note: "=HYPERLINK(1)", ended: null },
    { trial_id: "t1", seq: 2, note: 'said "hi", left', ended: true },
  ]);

  it("is CSV through the one CSV writer (formulas made inert, RFC 4180 quoting)", () => {
    expect(tableCsv(table)).toBe(
      'trial_id,seq,note,ended\r\nt1,1,\'=HYPERLINK(1),\r\nt1,2,"said ""hi"", left",true\r\n',
    );
  });

  it("is CSV for a script, as the analysis API writes it, with the text as it is", () => {
    expect(tableCsv(table, "script")).toBe(
      'trial_id,seq,note,ended\r\nt1,1,=HYPERLINK(1),\r\nt1,2,"said ""hi"", left",true\r\n',
    );
  });

  it("is JSON records keyed by column, an empty cell null", () => {
    expect(JSON.parse(tableJson(table))).toEqual([
      { trial_id: "t1", seq: 1, note: "=HYPERLINK(1)", ended: null },
      { trial_id: "t1", seq: 2, note: 'said "hi", left', ended: true },
    ]);
  });

  it("names a path's parameters", () => {
    expect(pathParameters("/studies/{studyId}/trials/{trialId}")).toEqual(["studyId", "trialId"]);
  });
});
