// A trial's recording can come in parts: the wizard's page closed mid-recording
// (the server finished what it held) and the wizard recorded again. Each part
// sits on the trial's clock at its offset from t0; between them nothing was
// recorded, and the analysis page says why.

export interface RecordingPart {
  id: string;
  /** Its start minus the trial's t0, in ms. */
  offsetMs: number | null;
  durationMs: number | null;
  /** Finished by the server because the page recording it went away. */
  cutOff: boolean;
}

export interface RecordingGap {
  fromMs: number;
  toMs: number;
  cause: string;
}

export const PAGE_CLOSED = "the wizard's page closed";
const STOPPED = "the recording was stopped";

const start = (part: RecordingPart) => part.offsetMs ?? 0;
const end = (part: RecordingPart) => start(part) + (part.durationMs ?? 0);

/** The parts in the order they were recorded. */
export const inOrder = <P extends RecordingPart>(parts: readonly P[]): P[] =>
  [...parts].sort((a, b) => start(a) - start(b));

/** What was not recorded between the parts, and after a part cut off until the trial's end, each with why. */
export function recordingGaps(parts: readonly RecordingPart[], trialEndMs: number): RecordingGap[] {
  const ordered = inOrder(parts);
  return ordered.flatMap((part, i) => {
    const next = ordered[i + 1];
    const to = next ? start(next) : part.cutOff ? trialEndMs : null;
    if (to === null || to <= end(part)) return [];
    return [{ fromMs: end(part), toMs: to, cause: part.cutOff ? PAGE_CLOSED : STOPPED }];
  });
}

/**
 * Where a moment of the trial is in the recording: the part playing then and
 * the seconds into it. In a gap, the next part from its start; after the
 * last, the last one's end; before the first, the first one's start.
 */
export function partAt(parts: readonly RecordingPart[], trialMs: number): { index: number; seconds: number } | null {
  const ordered = inOrder(parts);
  if (!ordered.length) return null;
  const index = ordered.findLastIndex((p) => start(p) <= trialMs);
  if (index === -1) return { index: 0, seconds: 0 };
  const part = ordered[index]!;
  if (part.durationMs === null || trialMs <= end(part)) return { index, seconds: (trialMs - start(part)) / 1000 };
  if (index + 1 < ordered.length) return { index: index + 1, seconds: 0 };
  return { index, seconds: part.durationMs / 1000 };
}

/** "3 minutes", "40 seconds": how much of a recording there is, in words. */
export function lengthWords(ms: number): string {
  const s = Math.round(ms / 1000);
  if (s < 90) return s === 1 ? "1 second" : `${s} seconds`;
  return `${Math.round(s / 60)} minutes`;
}

/** What the reopened wizard page says of a recording its page's closing cut off (no length: nothing of it arrived). */
export const cutOffWords = (stoppedAt: string, durationMs: number | null) =>
  `The recording stopped when the page closed at ${stoppedAt}; ${durationMs === null ? "none of it had reached the server" : `the ${lengthWords(durationMs)} before are kept`}.`;
