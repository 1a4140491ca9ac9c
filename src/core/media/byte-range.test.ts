import { describe, expect, it } from "vitest";
import { byteRange, type RangeAnswer } from "./byte-range";

const part = (start: number, end: number): RangeAnswer => ({ kind: "part", range: { start, end } });
const whole: RangeAnswer = { kind: "whole" };
const unsatisfiable: RangeAnswer = { kind: "unsatisfiable" };

describe("which bytes a Range header asks for, of a 100-byte file", () => {
  it.each<[string | null, RangeAnswer]>([
    [null, whole],
    ["", whole],
    ["bytes=0-9", part(0, 9)],
    ["bytes=10-", part(10, 99)],
    ["bytes=90-200", part(90, 99)],
    ["bytes=99-99", part(99, 99)],
    ["bytes=-10", part(90, 99)],
    ["bytes=-500", part(0, 99)],
    ["bytes=100-", unsatisfiable],
    ["bytes=150-160", unsatisfiable],
    ["bytes=-0", unsatisfiable],
    // Ignored, so the whole file: bad syntax, a backwards range, several ranges, another unit.
    ["bytes=-", whole],
    ["bytes=9-0", whole],
    ["bytes=0-1,5-6", whole],
    ["items=0-9", whole],
    ["bytes=a-b", whole],
  ])("%j", (header, answer) => {
    expect(byteRange(header, 100)).toEqual(answer);
  });

  it("has nothing to give of an empty file but the whole of it", () => {
    expect(byteRange("bytes=0-", 0)).toEqual(unsatisfiable);
    expect(byteRange("bytes=-5", 0)).toEqual(unsatisfiable);
    expect(byteRange(null, 0)).toEqual(whole);
  });
});
