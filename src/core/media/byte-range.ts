// Which bytes of a file a Range header asks for (RFC 9110 §14), for the
// player that seeks in a recording. One range only: a header the server
// cannot or need not honour (several ranges, bad syntax) is ignored and the
// whole file is sent, as the RFC allows.

/** First and last byte, both included. */
export interface ByteRange {
  start: number;
  end: number;
}

export type RangeAnswer = { kind: "whole" } | { kind: "part"; range: ByteRange } | { kind: "unsatisfiable" };

const WHOLE: RangeAnswer = { kind: "whole" };

export function byteRange(header: string | null, size: number): RangeAnswer {
  const m = /^bytes=(\d*)-(\d*)$/.exec((header ?? "").trim());
  if (!m || (!m[1] && !m[2])) return WHOLE;
  if (!m[1]) {
    // A suffix: the last N bytes.
    const length = Number(m[2]);
    if (length === 0 || size === 0) return { kind: "unsatisfiable" };
    return { kind: "part", range: { start: Math.max(0, size - length), end: size - 1 } };
  }
  const start = Number(m[1]);
  if (m[2] && Number(m[2]) < start) return WHOLE;
  if (start >= size) return { kind: "unsatisfiable" };
  return { kind: "part", range: { start, end: m[2] ? Math.min(Number(m[2]), size - 1) : size - 1 } };
}
