import { describe, expect, it } from "vitest";
import { accountKey, accountRefusal, windowCutoff } from "./sign-in-throttle";

const limit = { failures: 3, windowMinutes: 15 };
const start = new Date("2025-05-01T10:00:00Z");
const at = (minutes: number) => new Date(start.getTime() + minutes * 60_000);

describe("per-account sign-in limit", () => {
  it.each<[string, number, number, string | null]>([
    ["lets the first attempt through", 1, 0, null],
    ["lets the attempt that reaches the limit through", 3, 5, null],
    [
      "refuses the attempt past the limit, naming the minutes left",
      4,
      5,
      "Too many failed sign-ins for this account; try again in 10 minutes.",
    ],
    ["rounds the minutes left up", 4, 13.5, "Too many failed sign-ins for this account; try again in 2 minutes."],
    [
      "says one minute in the last minute",
      9,
      14.9,
      "Too many failed sign-ins for this account; try again in 1 minute.",
    ],
  ])("%s", (_name, failures, minutesIn, expected) => {
    expect(accountRefusal({ failures, windowStartedAt: start }, at(minutesIn), limit)).toBe(expected);
  });

  it("ends a window after its minutes", () => {
    expect(windowCutoff(at(15), limit)).toEqual(start);
  });

  it.each([
    ["Rosa@Example.org", "account:rosa@example.org"],
    [" rosa@example.org ", "account:rosa@example.org"],
  ])("keys %s as %s", (email, key) => {
    expect(accountKey(email)).toBe(key);
  });
});
