// Questionnaire answers as tidy CSV: one row per participant × item, in the
// order of the version they were shown, then a row per score.
import { csvField } from "../analysis/exports";
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

export const ANSWER_COLUMNS = ["participant", "trial_id", "questionnaire", "version", "item_id", "item", "answer"] as const;

const answerText = (value: unknown) => (Array.isArray(value) ? value.join("; ") : value === undefined ? "" : String(value));

export function answersCsv(responses: SubmittedResponse[]): string {
  const rows = responses.flatMap((r) => {
    const answers = (r.answers ?? {}) as Record<string, unknown>;
    const base = [r.participantCode, r.trialId ?? "", r.questionnaire, r.version];
    const itemRows = items(r.definition as Definition).map((item) => [...base, item.id, item.text, answerText(answers[item.id])]);
    const score = r.score as { score?: number; subscales?: Record<string, number> } | null;
    const scoreRows = score?.score === undefined ? [] : [[...base, "score", "score", score.score], ...Object.entries(score.subscales ?? {}).map(([name, value]) => [...base, `score.${name}`, name, value])];
    return [...itemRows, ...scoreRows];
  });
  return [ANSWER_COLUMNS.join(","), ...rows.map((row) => row.map(csvField).join(","))].join("\r\n") + "\r\n";
}
