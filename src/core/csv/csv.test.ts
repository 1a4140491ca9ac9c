import { describe, expect, it } from "vitest";
import { csvCell, csvDocument, type CsvValue } from "./csv";

describe("a CSV cell", () => {
  it.each<[CsvValue, string]>([
    // Plain values pass as they are.
    ["P001", "P001"],
    [4, "4"],
    [-3, "-3"],
    [12.5, "12.5"],
    [true, "true"],
    [null, ""],
    [undefined, ""],
    ["", ""],
    // RFC 4180 quoting.
    ["a,b", '"a,b"'],
    ['She said "hi"', '"She said ""hi"""'],
    ["two\nlines", '"two\nlines"'],
    // Text a spreadsheet would run as a formula is made inert.
    ['=HYPERLINK("http://x","y")', `"'=HYPERLINK(""http://x"",""y"")"`],
    ["=1+1", "'=1+1"],
    ["+1", "'+1"],
    ["-3", "'-3"],
    ["@SUM(A1:A2)", "'@SUM(A1:A2)"],
    ["\t=1+1", "'\t=1+1"],
    ["\r=1+1", `"'\r=1+1"`],
    // Only the first character counts.
    ["1+1", "1+1"],
    ["a=b", "a=b"],
    [" =1", " =1"],
  ])("writes %j as %s", (value, cell) => {
    expect(csvCell(value)).toBe(cell);
  });
});

describe("a CSV cell for a script", () => {
  it.each<[CsvValue, string]>([
    ["-5 looks away", "-5 looks away"],
    ["=1+1", "=1+1"],
    ['=HYPERLINK("http://x","y")', '"=HYPERLINK(""http://x"",""y"")"'],
    ["\r=1+1", '"\r=1+1"'],
    [-3, "-3"],
    [null, ""],
  ])("writes %j as %s, the text as it is", (value, cell) => {
    expect(csvCell(value, "script")).toBe(cell);
  });
});

describe("a CSV document", () => {
  it("writes the header, then a CRLF-ended line per row", () => {
    expect(
      csvDocument(
        ["a", "b"],
        [
          [1, "+x"],
          ["y", null],
        ],
      ),
    ).toBe("a,b\r\n1,'+x\r\ny,\r\n");
  });
});
