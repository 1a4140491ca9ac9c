// Agreement between two observers: each observer's codes of one set are cut
// into time slices (the code that holds in each, or "none"), the two sequences
// make a confusion table, and Cohen's kappa is read off the table. Pooling the
// tables of several trials gives a study's kappa. Pure: no clock, no I/O.
import type { AgreementWindow } from "./counted";
import type { CodeKind } from "./scheme";

/** One code event as agreement needs it; a state with no end yet holds to the end of the trial. */
export type CodeMark = { setId: string; codeId: string; kind: CodeKind; startMs: number; endMs: number | null };

/** The slice where neither a state nor a point event of the set was coded. */
export const NONE = "(none)";

/**
 * What an observer coded in each slice of [0, durationMs): a point event marks
 * the slice it falls in (the later one wins), otherwise the state that holds
 * at the slice's middle.
 */
export function sliceCodes(marks: CodeMark[], setId: string, durationMs: number, sliceMs: number): string[] {
  if (!(sliceMs > 0)) throw new Error(`The slice must be longer than 0 ms (it is ${sliceMs}).`);
  const count = Math.max(0, Math.ceil(durationMs / sliceMs));
  const slices: string[] = Array.from({ length: count }, () => NONE);
  const ofSet = marks.filter((m) => m.setId === setId).sort((a, b) => a.startMs - b.startMs);
  for (const m of ofSet.filter((m) => m.kind === "state")) {
    const end = m.endMs ?? durationMs;
    for (let i = Math.max(0, Math.floor(m.startMs / sliceMs)); i < count; i++) {
      const middle = (i + 0.5) * sliceMs;
      if (middle >= end) break;
      if (middle >= m.startMs) slices[i] = m.codeId;
    }
  }
  for (const m of ofSet.filter((m) => m.kind === "point")) {
    const i = Math.floor(m.startMs / sliceMs);
    if (i >= 0 && i < count) slices[i] = m.codeId;
  }
  return slices;
}

/** When a step of one trial held, in ms from the trial's start. */
export type StepSpan = { stepId: string; fromMs: number; toMs: number };

/** Each step from its entry to the next step's (or the trial's end), from the trial's step.entered events in order. */
export function stepSpans(entries: Array<{ stepId: string; relMs: number }>, durationMs: number): StepSpan[] {
  return entries.map((e, i) => ({ stepId: e.stepId, fromMs: e.relMs, toMs: entries[i + 1]?.relMs ?? durationMs }));
}

/** A trial as agreement reads it; `steps` is only needed for the "steps" window. */
export type AgreementTrial = { durationMs: number; a: CodeMark[]; b: CodeMark[]; steps?: StepSpan[] };

/**
 * The spans of one trial that count for one set, clipped to the trial: a
 * slice past the trial's end, or before anyone had coded, would count as
 * agreement on "nothing" though nobody watched it.
 */
export function windowSpans(
  trial: AgreementTrial,
  setId: string,
  window: AgreementWindow,
  stepIds: string[] = [],
): Array<[number, number]> {
  const end = trial.durationMs;
  if (window === "trial") return [[0, end]];
  if (window === "steps")
    return (trial.steps ?? [])
      .filter((s) => stepIds.includes(s.stepId))
      .map((s): [number, number] => [Math.max(0, s.fromMs), Math.min(end, s.toMs)]);
  const first = (marks: CodeMark[]) => Math.min(...marks.filter((m) => m.setId === setId).map((m) => m.startMs));
  return [[Math.max(0, first(trial.a), first(trial.b)), end]];
}

/** The codes of the slices whose middle lies in one of the spans. */
export function inWindow(slices: string[], spans: Array<[number, number]>, sliceMs: number): string[] {
  return slices.filter((_, i) => {
    const middle = (i + 0.5) * sliceMs;
    return spans.some(([from, to]) => middle >= from && middle < to);
  });
}

/** A confusion table: rows are observer A's codes, columns observer B's, in `categories` order. */
export type Confusion = { categories: string[]; counts: number[][] };

export function confusion(a: string[], b: string[], categories: string[]): Confusion {
  if (a.length !== b.length) throw new Error(`The two observers have ${a.length} and ${b.length} slices.`);
  const index = new Map(categories.map((c, i) => [c, i]));
  const counts = categories.map(() => categories.map(() => 0));
  a.forEach((code, s) => {
    const row = index.get(code);
    const col = index.get(b[s]!);
    if (row === undefined || col === undefined)
      throw new Error(`"${row === undefined ? code : b[s]}" is not a category.`);
    counts[row]![col]!++;
  });
  return { categories, counts };
}

/** Two tables of the same categories summed: a study's pooled table. */
export function pool(tables: Confusion[], categories: string[]): Confusion {
  const counts = categories.map(() => categories.map(() => 0));
  for (const t of tables)
    t.categories.forEach((r, i) =>
      t.categories.forEach((c, j) => {
        const row = categories.indexOf(r);
        const col = categories.indexOf(c);
        if (row < 0 || col < 0) throw new Error(`"${row < 0 ? r : c}" is not a category.`);
        counts[row]![col]! += t.counts[i]![j]!;
      }),
    );
  return { categories, counts };
}

export type Kappa = {
  n: number;
  /** Observed agreement: the share of slices both coded alike. */
  observed: number;
  /** Agreement expected by chance from each observer's own frequencies. */
  expected: number;
  /** Cohen's kappa, or null where it is undefined (no slices, or chance agreement is certain). */
  kappa: number | null;
};

/** Cohen's (1960) kappa: (p_o − p_e) / (1 − p_e), from a square confusion table. */
export function cohenKappa(counts: number[][]): Kappa {
  const n = counts.flat().reduce((s, x) => s + x, 0);
  if (n === 0) return { n, observed: 0, expected: 0, kappa: null };
  const rows = counts.map((r) => r.reduce((s, x) => s + x, 0));
  const cols = counts.map((_, j) => counts.reduce((s, r) => s + r[j]!, 0));
  const observed = counts.reduce((s, r, i) => s + r[i]!, 0) / n;
  const expected = rows.reduce((s, r, i) => s + (r / n) * (cols[i]! / n), 0);
  return { n, observed, expected, kappa: expected === 1 ? null : (observed - expected) / (1 - expected) };
}

/** Landis & Koch's (1977) words for a kappa, as papers report it. */
export function strength(kappa: number): string {
  if (kappa < 0) return "poor";
  if (kappa <= 0.2) return "slight";
  if (kappa <= 0.4) return "fair";
  if (kappa <= 0.6) return "moderate";
  if (kappa <= 0.8) return "substantial";
  return "almost perfect";
}

export type SetAgreement = Kappa & { setId: string; table: Confusion };

/**
 * Agreement of two observers on each set of codes over one trial (or several:
 * pass each trial's marks and duration), sliced every `sliceMs`, counting
 * only the slices of the window.
 */
export function agreement(
  sets: Array<{ id: string; codes: Array<{ id: string }> }>,
  trials: AgreementTrial[],
  sliceMs: number,
  window: AgreementWindow = "trial",
  stepIds: string[] = [],
): SetAgreement[] {
  return sets.map((set) => {
    const categories = [...set.codes.map((c) => c.id), NONE];
    const counted = (t: AgreementTrial, marks: CodeMark[]) =>
      inWindow(sliceCodes(marks, set.id, t.durationMs, sliceMs), windowSpans(t, set.id, window, stepIds), sliceMs);
    const table = pool(
      trials.map((t) => confusion(counted(t, t.a), counted(t, t.b), categories)),
      categories,
    );
    return { setId: set.id, table, ...cohenKappa(table.counts) };
  });
}
