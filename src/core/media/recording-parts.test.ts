import { describe, expect, it } from "vitest";
import { cutOffWords, lengthWords, PAGE_CLOSED, partAt, recordingGaps, type RecordingPart } from "./recording-parts";

const part = (id: string, offsetMs: number, durationMs: number | null, cutOff = false): RecordingPart => ({
  id,
  offsetMs,
  durationMs,
  cutOff,
});
// Cut off at 60 s when its page closed; recorded again from 90 s to 150 s.
const first = part("a", -2000, 62_000, true);
const second = part("b", 90_000, 60_000);

describe("a recording in parts", () => {
  it.each([
    ["one part stopped by the wizard", [part("a", 0, 10_000)], []],
    [
      "one part cut off: not recorded to the trial's end",
      [first],
      [{ fromMs: 60_000, toMs: 200_000, cause: PAGE_CLOSED }],
    ],
    [
      "cut off, then recorded again (in any order)",
      [second, first],
      [{ fromMs: 60_000, toMs: 90_000, cause: PAGE_CLOSED }],
    ],
    [
      "stopped, then recorded again",
      [part("a", 0, 10_000), part("b", 15_000, 1000)],
      [{ fromMs: 10_000, toMs: 15_000, cause: "the recording was stopped" }],
    ],
    ["a part cut off at the trial's very end", [part("a", 0, 200_000, true)], []],
  ])("has its gaps marked: %s", (_name, parts, gaps) => {
    expect(recordingGaps(parts, 200_000)).toEqual(gaps);
  });

  it.each([
    ["inside the first part", 10_000, { index: 0, seconds: 12 }],
    ["before the first part", -5000, { index: 0, seconds: 0 }],
    ["in the gap: the next part's start", 70_000, { index: 1, seconds: 0 }],
    ["inside the second part", 100_000, { index: 1, seconds: 10 }],
    ["after the last part: its end", 180_000, { index: 1, seconds: 60 }],
  ])("finds a moment %s", (_name, ms, at) => {
    expect(partAt([second, first], ms)).toEqual(at);
  });

  it("finds nothing without parts, and keeps playing a part whose length is unknown", () => {
    expect(partAt([], 0)).toBeNull();
    expect(partAt([part("a", 0, null)], 5000)).toEqual({ index: 0, seconds: 5 });
  });

  it.each([
    [1000, "1 second"],
    [40_400, "40 seconds"],
    [89_000, "89 seconds"],
    [180_000, "3 minutes"],
    [200_000, "3 minutes"],
  ])("says %i ms as %s", (ms, words) => {
    expect(lengthWords(ms)).toBe(words);
  });

  it("tells the reopened page what happened", () => {
    expect(cutOffWords("14:02", 180_000)).toBe(
      "The recording stopped when the page closed at 14:02; the 3 minutes before are kept.",
    );
    expect(cutOffWords("9:15", null)).toBe(
      "The recording stopped when the page closed at 9:15; none of it had reached the server.",
    );
  });
});
