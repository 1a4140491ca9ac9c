// Questionnaire answers as one long table: a row per participant × item, in
// the order of the version they were shown, with the instrument, the item's
// published sub-scale and whether it is scored reversed, and the participant's
// condition; then a row per score the instrument publishes, by its published
// name. A paper's analysis reads it as it is, with no outside key.
import { csvDocument, type CsvValue } from "../csv/csv";
import { items, type Definition } from "./definition";
import { INSTRUMENT_NAMES } from "./instruments";
import { itemScoring, publishedScores } from "./published-scores";

export interface SubmittedResponse {
  questionnaire: string;
  version: number;
  definition: unknown;
  participantCode: string;
  /** The participant's condition, if the study has conditions. */
  condition: string | null;
  trialId: string | null;
  answers: unknown;
  score: unknown;
}

export const ANSWER_COLUMNS = [
  "participant",
  "condition",
  "trial_id",
  "questionnaire",
  "instrument",
  "version",
  "measure",
  "item_id",
  "item",
  "subscale",
  "reverse_scored",
  "answer",
] as const;

// A number answer stays a number (a scale's -3 is written -3); text and choices are text.
const answerCell = (value: unknown): CsvValue =>
  Array.isArray(value)
    ? value.join("; ")
    : typeof value === "number"
      ? value
      : value === undefined || value === null
        ? null
        : String(value);

export function answersCsv(responses: SubmittedResponse[]): string {
  return csvDocument(ANSWER_COLUMNS, answerRows(responses));
}

/** The cells of answersCsv: the analysis API returns them as CSV or JSON. */
export function answerRows(responses: SubmittedResponse[]): CsvValue[][] {
  return responses.flatMap((r): CsvValue[][] => {
    const answers = (r.answers ?? {}) as Record<string, unknown>;
    const definition = r.definition as Definition;
    const instrument = definition.instrument ?? null;
    const base = [
      r.participantCode,
      r.condition,
      r.trialId,
      r.questionnaire,
      instrument ? INSTRUMENT_NAMES[instrument] : null,
      r.version,
    ];
    const itemRows = items(definition).map((item) => {
      const place = itemScoring(instrument, item.id);
      return [
        ...base,
        "answer",
        item.id,
        item.text,
        place?.subscale ?? null,
        place ? place.reverse : null,
        answerCell(answers[item.id]),
      ];
    });
    const scoreRows = publishedScores(instrument, r.score as Parameters<typeof publishedScores>[1]).map((s) => [
      ...base,
      "score",
      null,
      s.name,
      s.subscale,
      null,
      s.value,
    ]);
    return [...itemRows, ...scoreRows];
  });
}
