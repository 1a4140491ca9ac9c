// What the study's tables (the Results tab, results by condition) read of one
// trial's fidelity report. Small and JSON-safe, so it is kept once computed
// (src/store/trial-figures.ts) and the Results tab reads a row per trial
// instead of folding every trial's log again.
import type { FidelityReport } from "./fidelity";

/**
 * Raise it whenever what is kept could come out differently for the same log:
 * a change to fidelityReport, to what reportFigures keeps, or to how a
 * protocol snapshot is read (readSnapshot). Every copy kept under another
 * version is then computed again.
 */
// 2: the answers recorded (answers), for the Results tab's counts per answer.
// 3: how many times each step was entered (steps[].entered), round loops.
export const FIGURES_VERSION = 3;

export type ReportFigures = Pick<
  FidelityReport,
  "steps" | "branches" | "answers" | "deviations" | "totals" | "executionFidelity" | "completed"
>;

/** The report without its per-action lists, which only the trial's own analysis page shows. */
export function reportFigures(report: FidelityReport): ReportFigures {
  const { steps, branches, answers, deviations, totals, executionFidelity, completed } = report;
  return { steps, branches, answers, deviations, totals, executionFidelity, completed };
}
