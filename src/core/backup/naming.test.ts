import { describe, expect, it } from "vitest";
import { backupName, expiredBackups } from "./naming";

const at = new Date("2026-11-26T23:47:12.045Z");

describe("backupName", () => {
  it.each<[string, number, string]>([
    ["the first attempt carries the time to the millisecond", 1, "hristudio-2026-11-26-234712-045.tar"],
    ["a later attempt in the same millisecond gets a counter", 2, "hristudio-2026-11-26-234712-045-2.tar"],
    ["and so on", 12, "hristudio-2026-11-26-234712-045-12.tar"],
  ])("%s", (_, attempt, expected) => {
    expect(backupName(at, attempt)).toBe(expected);
  });

  it("gives two backups a millisecond apart two names", () => {
    expect(backupName(at)).not.toBe(backupName(new Date(at.getTime() + 1)));
  });
});

describe("expiredBackups", () => {
  const a = "hristudio-2026-11-24-010000-000.tar";
  const b = "hristudio-2026-11-25-010000-000.tar";
  const b2 = "hristudio-2026-11-25-010000-000-2.tar";
  const b10 = "hristudio-2026-11-25-010000-000-10.tar";
  const c = "hristudio-2026-11-26-010000-000.tar";

  it.each<[string, string[], number, string[]]>([
    ["keeps the newest, removes the rest", [c, a, b], 2, [a]],
    ["nothing when there are no more than kept", [a, b], 2, []],
    ["counters in order: -10 is newer than -2", [b10, b2, b, c], 2, [b, b2]],
    [
      "never a file it did not name, nor one being written",
      ["study.tar", `${a}.part`, "notes.txt", "hristudio-old.tar", a, b],
      1,
      [a],
    ],
  ])("%s", (_, files, keep, expected) => {
    expect(expiredBackups(files, keep)).toEqual(expected);
  });
});
