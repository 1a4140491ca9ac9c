import { describe, expect, it } from "vitest";
import { BLOCK, paddingAfter, readTarHeader, splitName, tarHeader } from "./tar";

const when = new Date("2026-03-01T12:00:00Z");

describe("tar headers", () => {
  it.each([
    ["manifest.json", 0],
    ["database/trial_events.copy", 123_456],
    ["media/recordings/0b7c2c8e-1f7e-4c8e-9d39-0d2f3f1d9a11.webm", 4 * 1024 ** 3],
    ["media/" + "a".repeat(120) + "/" + "b".repeat(90), 1],
    ["huge", 9 * 1024 ** 3],
  ])("%s of %i bytes reads back as it was written", (name, size) => {
    expect(readTarHeader(tarHeader(name, size, when), 0)).toEqual({ name, size, type: "0" });
  });

  it("writes what POSIX tar expects where it expects it", () => {
    const header = tarHeader("manifest.json", 10, when);
    const text = new TextDecoder().decode(header);
    expect(header.length).toBe(BLOCK);
    expect(text.slice(0, 13)).toBe("manifest.json");
    expect(text.slice(124, 135)).toBe("00000000012");
    expect(text.slice(257, 265)).toBe("ustar\x0000");
  });

  it("reads the zero block as the end of the archive", () => {
    expect(readTarHeader(new Uint8Array(BLOCK), 0)).toBeNull();
  });

  it.each([
    ["a changed byte", (b: Uint8Array) => (b[3] = 65), "damaged at byte 1024"],
    ["a short block", (b: Uint8Array) => b.subarray(0, 100), "ends in the middle of a header (at byte 1024)"],
  ])("refuses %s, saying where", (_, spoil, message) => {
    const block = tarHeader("manifest.json", 10, when);
    const spoilt = spoil(block);
    expect(() => readTarHeader(spoilt instanceof Uint8Array ? spoilt : block, 1024)).toThrow(message);
  });

  it.each([
    ["short", { prefix: "", name: "short" }],
    [`p/${"n".repeat(100)}`, { prefix: "p", name: "n".repeat(100) }],
  ])("splits %s into prefix and name", (path, expected) => {
    expect(splitName(path)).toEqual(expected);
  });

  it("refuses a name that cannot be split", () => {
    expect(() => splitName("x".repeat(101))).toThrow("too long to store in the backup file");
  });

  it.each([
    [0, 0],
    [1, 511],
    [512, 0],
    [513, 511],
  ])("pads %i bytes with %i", (size, padding) => {
    expect(paddingAfter(size)).toBe(padding);
  });
});
