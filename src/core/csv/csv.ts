// The one CSV writer every export uses: RFC 4180 quoting, and, in files meant
// for spreadsheets, text that a spreadsheet would run as a formula made inert.
//
// A cell starting with = + - @ (or a tab or carriage return, which some
// spreadsheets skip before looking) is a formula to Excel, LibreOffice and
// Google Sheets: an answer such as =HYPERLINK("http://x","y") would become a
// live link in the researcher's spreadsheet. OWASP's advice: prefix such text
// with a single quote, so it shows as the text that was typed. Numbers are
// written as numbers (-3 stays -3); only text is neutralised. A script's
// reader (the analysis API, read by R or pandas) runs no formulas: there the
// guard would only change the data (a label "-5 looks away" read as
// "'-5 looks away"), so its CSV is written as the text is.

const FORMULA_START = /^[=+\-@\t\r]/;

export type CsvValue = string | number | boolean | null | undefined;

/** Who reads the file: a spreadsheet (formulas made inert) or a script (the text as it is). */
export type CsvReader = "spreadsheet" | "script";

/** One cell: for a spreadsheet, text that could run as a formula is prefixed with '; then quoted if it must be. */
export function csvCell(value: CsvValue, reader: CsvReader = "spreadsheet"): string {
  if (value === null || value === undefined) return "";
  const guard = reader === "spreadsheet" && typeof value === "string" && FORMULA_START.test(value);
  const text = guard ? `'${value}` : String(value);
  return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

/** Rows as lines of a document, each ended by CRLF: a document written a batch of rows at a time. */
export function csvLines(rows: ReadonlyArray<readonly CsvValue[]>, reader: CsvReader = "spreadsheet"): string {
  return rows.map((row) => `${row.map((value) => csvCell(value, reader)).join(",")}\r\n`).join("");
}

/** A whole document: the header, then one line per row, each line ended by CRLF. */
export function csvDocument(
  header: readonly string[],
  rows: ReadonlyArray<readonly CsvValue[]>,
  reader: CsvReader = "spreadsheet",
): string {
  return csvLines([header, ...rows], reader);
}
