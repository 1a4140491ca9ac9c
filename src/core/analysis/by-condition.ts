// Results by condition: the comparison most studies exist for. Each measure
// (execution fidelity, deviations, time in each step, the whole trial's
// duration, each questionnaire's score) described per condition with n, mean,
// sample SD, median and range, as a paper's table reports them; and the
// participants' answers, counted per question, per answer, per condition.
import { csvDocument } from "../csv/csv";
import type { Instrument } from "../questionnaires/definition";
import { publishedScores } from "../questionnaires/published-scores";
import { describe, studySummary, type Description, type TrialFigures } from "./study-summary";

export type Unit = "%" | "count" | "ms" | "score";

export interface Measure {
  measure: string;
  unit: Unit;
  /** One entry per condition, in the order of `ByCondition.conditions`; null where it has no value. */
  byCondition: Array<{ condition: string | null; stats: Description | null }>;
}

/** One question's answers: every answer it offered (then any other given), each counted per condition. */
export interface AnswerCounts {
  question: string;
  /** `byCondition` in the order of `ByCondition.conditions`. */
  answers: Array<{ answer: string; byCondition: Array<{ condition: string | null; count: number }> }>;
}

export interface ByCondition {
  conditions: Array<{ condition: string | null; trials: number }>;
  measures: Measure[];
  answers: AnswerCounts[];
}

/** A submitted questionnaire's stored score ({ score, subscales } for a standard instrument), with the participant's condition. */
export interface ConditionScore {
  condition: string | null;
  questionnaire: string;
  /** The standard instrument it is, which says what its scores are named; null for the study's own. */
  instrument: Instrument | null;
  score: unknown;
}

type Stored = Parameters<typeof publishedScores>[1];

/** Named conditions alphabetically; trials of participants without a condition last. */
function conditionOrder(a: string | null, b: string | null) {
  if (a === b) return 0;
  if (a === null) return 1;
  if (b === null) return -1;
  return a.localeCompare(b);
}

export function resultsByCondition(trials: TrialFigures[], scores: ConditionScore[]): ByCondition {
  const names = [...new Set([...trials.map((t) => t.condition), ...scores.map((s) => s.condition)])].sort(
    conditionOrder,
  );
  const groups = names.map((condition) => {
    const group = trials.filter((t) => t.condition === condition);
    return { condition, group, rows: studySummary(group).trials };
  });
  const measure = (name: string, unit: Unit, values: (g: (typeof groups)[number]) => number[]): Measure => ({
    measure: name,
    unit,
    byCondition: groups.map((g) => ({ condition: g.condition, stats: describe(values(g)) })),
  });

  // Steps by name, in protocol order as the trials met them (conditions may run different experiments).
  const stepNames = [...new Set(trials.flatMap((t) => t.report.steps.map((s) => s.name)))];
  const stepMeasures = stepNames.map((name) =>
    measure(`Time in step: ${name}`, "ms", ({ group }) =>
      group.flatMap(({ report }) =>
        report.steps.flatMap((s) => (s.name === name && s.durationMs !== null ? [s.durationMs] : [])),
      ),
    ),
  );

  // Each score measure's values, with the condition they came from, in the order first met: the scores the
  // instrument publishes, by their published names (no overall Godspeed score: the instrument defines none).
  const scoreValues = new Map<string, Array<[string | null, number]>>();
  for (const s of scores)
    for (const { subscale, value } of publishedScores(s.instrument, s.score as Stored)) {
      const name = `Questionnaire score: ${s.questionnaire}${subscale ? ` (${subscale})` : ""}`;
      scoreValues.set(name, [...(scoreValues.get(name) ?? []), [s.condition, value]]);
    }
  const scoreMeasures = [...scoreValues].map(([name, values]) =>
    measure(name, "score", ({ condition }) => values.flatMap(([c, v]) => (c === condition ? [v] : []))),
  );

  return {
    conditions: groups.map(({ condition, group }) => ({ condition, trials: group.length })),
    measures: [
      measure("Execution fidelity", "%", ({ rows }) => rows.map((r) => r.executionFidelity)),
      measure("Deviations per trial", "count", ({ rows }) => rows.map((r) => r.deviations)),
      measure("Trial duration", "ms", ({ rows }) => rows.flatMap((r) => (r.durationMs === null ? [] : [r.durationMs]))),
      ...stepMeasures,
      ...scoreMeasures,
    ],
    answers: answerCounts(groups),
  };
}

/**
 * Questions by their text, in the order first met (conditions may run
 * different experiments that ask the same question); an answer recorded
 * twice in one trial (a question asked again) counts twice.
 */
function answerCounts(groups: Array<{ condition: string | null; group: TrialFigures[] }>): AnswerCounts[] {
  const questions = new Map<string, Set<string>>();
  for (const { group } of groups)
    for (const { report } of group)
      for (const a of report.answers) {
        const answers = questions.get(a.question) ?? new Set();
        for (const option of [...a.options, a.answer]) answers.add(option);
        questions.set(a.question, answers);
      }
  return [...questions].map(([question, answers]) => ({
    question,
    answers: [...answers].map((answer) => ({
      answer,
      byCondition: groups.map(({ condition, group }) => ({
        condition,
        count: group
          .flatMap(({ report }) => report.answers)
          .filter((a) => a.question === question && a.answer === answer).length,
      })),
    })),
  }));
}

// A count is no sample: mean, sd, median, min and max stay empty (every row has every column, for read.csv).
const NO_FIGURES = [null, null, null, null, null];

/** The measure an answer's count is in the tidy table: `Answers to “Where did Kai go?”: Mars`. */
const answerMeasure = (question: string, answer: string) => `Answers to “${question}”: ${answer}`;

/**
 * The tidy table: one row per condition × measure, the unit in the measure's name, durations in ms; then one
 * row per condition × question × answer, the times it was recorded in `n` (what the Results tab counts).
 */
export function byConditionCsv({ measures, answers }: ByCondition): string {
  const label = (m: Measure) => (m.unit === "ms" || m.unit === "%" ? `${m.measure} (${m.unit})` : m.measure);
  return csvDocument(
    ["condition", "measure", "n", "mean", "sd", "median", "min", "max"],
    [
      ...measures.flatMap((m) =>
        m.byCondition.map(({ condition, stats }) => [
          condition,
          label(m),
          stats?.n ?? 0,
          stats?.mean,
          stats?.sd,
          stats?.median,
          stats?.min,
          stats?.max,
        ]),
      ),
      ...answers.flatMap(({ question, answers }) =>
        answers.flatMap(({ answer, byCondition }) =>
          byCondition.map(({ condition, count }) => [condition, answerMeasure(question, answer), count, ...NO_FIGURES]),
        ),
      ),
    ],
  );
}
