// The study level: every trial's fidelity figures in one table, each step's
// timing across participants, and how consistently the protocol was run.
// Published reviews find that WoZ studies rarely report wizard error; this is
// the number to report.
import type { ReportFigures } from "./trial-figures";

export interface TrialFigures {
  trialId: string;
  participantCode: string | null;
  condition: string | null;
  /** Its fidelity report, or the part of it these tables read. */
  report: ReportFigures;
}

export interface Spread {
  n: number;
  median: number;
  min: number;
  max: number;
}

export interface StudySummary {
  trials: Array<{
    trialId: string;
    participantCode: string | null;
    condition: string | null;
    completed: boolean;
    executionFidelity: number;
    executed: number;
    planned: number;
    deviations: number;
    branchesByHand: number;
    unscripted: number;
    /** From the first step entered to the end of the last, in ms. */
    durationMs: number | null;
  }>;
  /** Per step (by name, in protocol order): how long participants spent in it. */
  steps: Array<{ name: string; durationMs: Spread | null; reachedBy: number }>;
  consistency: {
    trials: number;
    completed: number;
    meanFidelity: number | null;
    sdFidelity: number | null;
    /** Trials run exactly as scripted: no deviation of any kind. */
    withoutDeviation: number;
    deviationsByKind: Record<string, number>;
  };
}

export function spread(values: number[]): Spread | null {
  if (!values.length) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length / 2;
  const median = sorted.length % 2 ? sorted[Math.floor(mid)]! : (sorted[mid - 1]! + sorted[mid]!) / 2;
  return { n: sorted.length, median, min: sorted[0]!, max: sorted.at(-1)! };
}

const sum = (values: number[]) => values.reduce((a, b) => a + b, 0);

export interface Description extends Spread {
  mean: number;
  /** The sample SD (n − 1); null for a single value. */
  sd: number | null;
}

/** What a paper reports of a measure: n, mean, sample SD, median and range. */
export function describe(values: number[]): Description | null {
  const s = spread(values);
  if (!s) return null;
  const mean = sum(values) / values.length;
  const sd = values.length < 2 ? null : Math.sqrt(sum(values.map((v) => (v - mean) ** 2)) / (values.length - 1));
  return { ...s, mean, sd };
}

export function studySummary(trials: TrialFigures[]): StudySummary {
  const rows = trials.map(({ trialId, participantCode, condition, report }) => {
    const timed = report.steps.filter((s) => s.enteredMs !== null);
    const first = timed[0]?.enteredMs ?? null;
    const last = timed.length ? Math.max(...timed.map((s) => s.leftMs ?? s.enteredMs!)) : null;
    return {
      trialId,
      participantCode,
      condition,
      completed: report.completed,
      executionFidelity: report.executionFidelity,
      executed: report.totals.executed,
      planned: report.totals.planned,
      deviations: sum(Object.values(report.deviations)),
      branchesByHand: report.branches.byHand,
      unscripted: report.totals.unscripted,
      durationMs: first !== null && last !== null ? last - first : null,
    };
  });
  const stepNames: string[] = [];
  for (const { report } of trials)
    for (const s of report.steps) if (!stepNames.includes(s.name)) stepNames.push(s.name);
  const steps = stepNames.map((name) => {
    const timings = trials.flatMap(({ report }) => report.steps.filter((s) => s.name === name));
    return {
      name,
      reachedBy: timings.filter((s) => s.reached).length,
      durationMs: spread(timings.flatMap((s) => (s.durationMs === null ? [] : [s.durationMs]))),
    };
  });
  const fidelity = describe(rows.map((r) => r.executionFidelity));
  const deviationsByKind: Record<string, number> = {};
  for (const { report } of trials)
    for (const [kind, n] of Object.entries(report.deviations))
      deviationsByKind[kind] = (deviationsByKind[kind] ?? 0) + n;
  return {
    trials: rows,
    steps,
    consistency: {
      trials: rows.length,
      completed: rows.filter((r) => r.completed).length,
      meanFidelity: fidelity?.mean ?? null,
      sdFidelity: fidelity?.sd ?? null,
      withoutDeviation: rows.filter((r) => r.deviations === 0).length,
      deviationsByKind,
    },
  };
}
