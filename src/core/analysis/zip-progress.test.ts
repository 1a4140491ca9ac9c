import { strToU8, zipSync } from "fflate";
import { describe, expect, it } from "vitest";
import { isTrialRecord, zipEntryCounter } from "./zip-progress";

// A zip of three trials as the study's archive names them, with incompressible content between headers.
const noise = (n: number) => Uint8Array.from({ length: n }, (_, i) => (i * 7919) % 251);
const zip = zipSync(
  {
    "README.txt": strToU8("HRIStudio study archive"),
    "trials/a.json": noise(3000),
    "trials/a-events.csv": noise(500),
    "trials/b.json": noise(10),
    "trials/c.json": noise(4000),
    "trials/c.eaf": noise(100),
  },
  { level: 0 },
);

const countIn = (chunks: Uint8Array[]) => {
  const count = zipEntryCounter(isTrialRecord);
  return chunks.map(count);
};
const split = (bytes: Uint8Array, size: number) =>
  Array.from({ length: Math.ceil(bytes.length / size) }, (_, i) => bytes.subarray(i * size, (i + 1) * size));

describe("counting the trials of a streamed zip as its bytes arrive", () => {
  it.each([
    { how: "the whole zip at once", chunks: [zip] },
    { how: "one byte at a time", chunks: split(zip, 1) },
    { how: "chunks that cut headers and names", chunks: split(zip, 17) },
    { how: "large chunks", chunks: split(zip, 4096) },
  ])("$how: three trials, counted once each", ({ chunks }) => {
    const counts = countIn(chunks);
    expect(counts.at(-1)).toBe(3);
    // Never counts back, never past the end.
    expect(counts).toEqual([...counts].sort((a, b) => a - b));
  });

  it("counts a trial only once its header has arrived whole", () => {
    const at = zip.findIndex((_, i) => String.fromCharCode(...zip.subarray(i, i + 13)) === "trials/b.json");
    const count = zipEntryCounter(isTrialRecord);
    expect(count(zip.subarray(0, at + 5))).toBe(1);
    expect(count(zip.subarray(at + 5))).toBe(3);
  });

  it.each([
    ["trials/0b9c.json", true],
    ["trials/0b9c-events.csv", false],
    ["trials/0b9c.eaf", false],
    ["study.json", false],
    ["trials/x/y.json", false],
  ])("%s is a trial's record: %s", (name, expected) => {
    expect(isTrialRecord(name as string)).toBe(expected);
  });
});
