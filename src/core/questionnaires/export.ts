// Questionnaire answers as tidy CSV: one row per participant × item, in the
// order of the version they were shown, then a row per score.
import { csvDocument, type CsvValue } from "../csv/csv";
import { items, type Definition } from "./definition";

export interface SubmittedResponse {
  questionnaire: string;
  version: number;
  definition: unknown;
  participantCode: string;
  trialId: string | null;
  answers: unknown;
  score: unknown;
}

export const ANSWER_COLUMNS = [
  "participant",
  "trial_id",
  "questionnaire",
  "version",
  "item_id",
  "item",
  "answer",
] as const;

// A number answer stays a number (a scale's -3 is written -3); text and choices are text.
const answerCell = (value: unknown): CsvValue =>
  Array.isArray(value)
    ? value.join("; ")
    : typeof value === "number"
      ? value
      : value === undefined || value === null
        ? ""
        : String(value);

export function answersCsv(responses: SubmittedResponse[]): string {
  return csvDocument(ANSWER_COLUMNS, answerRows(responses));
}

/** The cells of answersCsv: the analysis API returns them as CSV or JSON. */
export function answerRows(responses: SubmittedResponse[]): CsvValue[][] {
  return responses.flatMap((r): CsvValue[][] => {
    const answers = (r.answers ?? {}) as Record<string, unknown>;
    const base = [r.participantCode, r.trialId ?? "", r.questionnaire, r.version];
    const itemRows = items(r.definition as Definition).map((item) => [
      ...base,
      item.id,
      item.text,
      answerCell(answers[item.id]),
    ]);
    const score = r.score as { score?: number; subscales?: Record<string, number> } | null;
    const scoreRows =
      score?.score === undefined
        ? []
        : [
            [...base, "score", "score", score.score],
            ...Object.entries(score.subscales ?? {}).map(([name, value]) => [...base, `score.${name}`, name, value]),
          ];
    return [...itemRows, ...scoreRows];
  });
}
