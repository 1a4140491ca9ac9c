import { describe, expect, it } from "vitest";
import { startTimeOf } from "./start-time";

const tail = "S 1 1234 1234 0 -1 4194560 100 0 0 0 5 3 0 0 20 0 1 0 987654 12345678 900 18446744073709551615";

describe("a process's start time from /proc/<pid>/stat", () => {
  it.each<[string, string, string | null]>([
    ["a plain name", `4321 (bun) ${tail}`, "987654"],
    ["a name with spaces", `4321 (Web Content) ${tail}`, "987654"],
    ["a name with parentheses", `4321 (a) b (c)) ${tail}`, "987654"],
    ["a trailing newline", `4321 (sleep) ${tail}\n`, "987654"],
    ["no name", "4321 bun S 1", null],
    ["too few fields", "4321 (bun) S 1 1234", null],
    ["a start that is not a number", `4321 (bun) ${tail.replace("987654", "x")}`, null],
    ["nothing", "", null],
  ])("%s", (_, stat, expected) => {
    expect(startTimeOf(stat)).toBe(expected);
  });
});
