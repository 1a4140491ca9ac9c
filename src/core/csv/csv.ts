// The one CSV writer every export uses: RFC 4180 quoting, and text that a
// spreadsheet would run as a formula made inert.
//
// A cell starting with = + - @ (or a tab or carriage return, which some
// spreadsheets skip before looking) is a formula to Excel, LibreOffice and
// Google Sheets: an answer such as =HYPERLINK("http://x","y") would become a
// live link in the researcher's spreadsheet. OWASP's advice: prefix such text
// with a single quote, so it shows as the text that was typed. Numbers are
// written as numbers (-3 stays -3); only text is neutralised.

const FORMULA_START = /^[=+\-@\t\r]/;

export type CsvValue = string | number | boolean | null | undefined;

/** One cell: text that could run as a formula is prefixed with ', then quoted if it must be. */
export function csvCell(value: CsvValue): string {
  if (value === null || value === undefined) return "";
  const text = typeof value === "string" ? (FORMULA_START.test(value) ? `'${value}` : value) : String(value);
  return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

/** Rows as lines of a document, each ended by CRLF: a document written a batch of rows at a time. */
export function csvLines(rows: ReadonlyArray<readonly CsvValue[]>): string {
  return rows.map((row) => `${row.map(csvCell).join(",")}\r\n`).join("");
}

/** A whole document: the header, then one line per row, each line ended by CRLF. */
export function csvDocument(header: readonly string[], rows: ReadonlyArray<readonly CsvValue[]>): string {
  return csvLines([header, ...rows]);
}
