import { describe, expect, it } from "vitest";
import { askedAt, droppedReason, ROBOT_ACTION_FRESH_MS, staleness } from "./freshness";
import type { Command } from "./types";

describe("when the wizard asked, on the runtime's clock", () => {
  it.each<[string, number | undefined, number | null, ReturnType<typeof askedAt>]>([
    ["no page time: when the runtime read it", undefined, 0, { ok: true, at: 10_000 }],
    ["no offset measured yet: when the runtime read it", 9000, null, { ok: true, at: 10_000 }],
    ["a page 5 s ahead, asked 1 s ago", 14_000, 5000, { ok: true, at: 9000 }],
    ["a page 5 s behind, asked 20 s ago", -15_000, -5000, { ok: true, at: -10_000 }],
    ["a little ahead of now (the offset drifted): now", 10_500, 0, { ok: true, at: 10_000 }],
  ])("%s", (_, pageTime, offset, expected) => {
    expect(askedAt(pageTime, offset, 10_000)).toEqual(expected);
  });

  it("refuses a page clock in the runtime's future, saying so", () => {
    const asked = askedAt(40_000, 0, 10_000);
    expect(asked).toEqual({ ok: false, reason: expect.stringMatching(/page's clock is 30 s ahead/) });
  });
});

describe("freshness limits", () => {
  it.each<[Command["kind"], number, boolean]>([
    ["trigger", ROBOT_ACTION_FRESH_MS, false],
    ["trigger", ROBOT_ACTION_FRESH_MS + 1, true],
    ["next", 20_000, true],
    ["unscripted", 20_000, true],
    ["emergency_stop", 3_600_000, false],
    ["abort", 3_600_000, false],
    ["completed", 3_600_000, false],
    ["note", 3_600_000, false],
  ])("%s asked %i ms ago is stale: %s", (kind, age, stale) => {
    expect(staleness(kind, 0, age) !== null).toBe(stale);
  });

  it("says how old, the limit and where it was dropped", () => {
    expect(droppedReason("the robot link", { ageMs: 20_400, limitMs: 3000 })).toBe(
      "Not sent: asked for 20.4 s ago, longer than the 3 s it stays worth doing, so it was dropped at the robot link rather than done late. Ask again if you still want it.",
    );
  });
});
