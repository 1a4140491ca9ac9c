// A tidy table (named columns, one row per observation), written as CSV with
// the one CSV writer, or as JSON records: what the analysis API returns.
import { csvDocument, type CsvReader, type CsvValue } from "@/core/csv/csv";

export interface Table {
  columns: readonly string[];
  rows: CsvValue[][];
}

/** A row named by its columns: the compiler checks every column is filled. */
export type Row<C extends readonly string[]> = Record<C[number], CsvValue>;

export function tableOf<C extends readonly string[]>(columns: C, rows: ReadonlyArray<Row<C>>): Table {
  return { columns, rows: rows.map((row) => columns.map((c) => row[c as C[number]])) };
}

/** For a spreadsheet unless told: the analysis API's CSV is read by scripts. */
export const tableCsv = (table: Table, reader: CsvReader = "spreadsheet") =>
  csvDocument(table.columns, table.rows, reader);

/** One object per row, keyed by column (an empty cell is null), as pandas' and R's JSON readers expect. */
export const tableRecords = (table: Table): Array<Record<string, unknown>> =>
  table.rows.map((row) => Object.fromEntries(table.columns.map((c, i) => [c, row[i] === undefined ? null : row[i]])));

export const tableJson = (table: Table): string => JSON.stringify(tableRecords(table));
