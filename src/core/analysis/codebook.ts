// The study zip's codebook.csv: every column of every CSV file in the zip,
// with its type, unit and allowed values, written from the one declaration
// of the columns (columns.ts) the analysis API is described from.
import { csvDocument } from "@/core/csv/csv";
import { type Column, TABLE_COLUMNS } from "./columns";

/** The zip's CSV files, each with the table whose columns it has. */
export const CODEBOOK_FILES = [
  ["trials/<id>-events.csv", "events"],
  ["trials/<id>-samples.csv", "samples"],
  ["codes.csv", "codes"],
  ["questionnaire-answers.csv", "answers"],
] as const satisfies ReadonlyArray<readonly [string, keyof typeof TABLE_COLUMNS]>;

export const CODEBOOK_COLUMNS = ["file", "variable", "type", "unit", "allowed_values", "may_be_empty", "description"];

export function codebookCsv(): string {
  return csvDocument(
    CODEBOOK_COLUMNS,
    CODEBOOK_FILES.flatMap(([file, table]) =>
      Object.entries(TABLE_COLUMNS[table] as Record<string, Column>).map(([variable, c]) => [
        file,
        variable,
        c.type,
        c.unit ?? null,
        c.values?.join("; ") ?? null,
        c.optional ?? false,
        c.description,
      ]),
    ),
  );
}
