import { describe, expect, it } from "vitest";
import {
  clockOffset,
  HEARTBEAT_EVERY_MS,
  PAGE_GONE_AFTER_MS,
  pageGone,
  RUNTIME_SILENT_AFTER_MS,
  type RuntimeLink,
  runtimeLink,
  watchingSince,
} from "./heartbeat";

describe("the page's view of its runtime", () => {
  it.each<[string, number, number, RuntimeLink]>([
    ["answered just now", 10_000, 10_000, "live"],
    ["answered a ping ago", 10_000, 10_000 + HEARTBEAT_EVERY_MS, "live"],
    ["at the limit", 10_000, 10_000 + RUNTIME_SILENT_AFTER_MS, "live"],
    ["just past the limit", 10_000, 10_000 + RUNTIME_SILENT_AFTER_MS + 1, "silent"],
    ["frozen for 20 s", 10_000, 30_000, "silent"],
  ])("%s", (_, answeredAt, now, link) => {
    expect(runtimeLink(answeredAt, now)).toBe(link);
  });

  it("shows a runtime that stopped right after answering silent within 2 s, checking once a ping", () => {
    // The page looks at each ping; the worst case is a look just before the limit passes.
    const answeredAt = 0;
    let now = answeredAt + 1;
    while (runtimeLink(answeredAt, now) === "live") now += HEARTBEAT_EVERY_MS;
    expect(now - answeredAt).toBeLessThanOrEqual(2000);
  });
});

describe("the runtime's view of its pages", () => {
  it.each<[string, { heardAt: number; since: number; now: number }, boolean]>([
    ["heard a ping ago", { heardAt: 50_000, since: 0, now: 50_500 }, false],
    ["silent up to the limit", { heardAt: 50_000, since: 0, now: 50_000 + PAGE_GONE_AFTER_MS }, false],
    ["silent past the limit", { heardAt: 50_000, since: 0, now: 50_001 + PAGE_GONE_AFTER_MS }, true],
    [
      "silent while the runtime itself was frozen: counted from its waking",
      { heardAt: 0, since: 25_000, now: 26_000 },
      false,
    ],
    ["silent for the limit after the runtime woke", { heardAt: 0, since: 25_000, now: 35_001 }, true],
  ])("%s", (_, { heardAt, since, now }, gone) => {
    expect(pageGone(heardAt, since, now)).toBe(gone);
  });

  it.each<[string, { since: number; lookedAt: number; now: number }, number]>([
    ["looking on time: still watching since the start", { since: 0, lookedAt: 20_000, now: 20_500 }, 0],
    ["a look a little late (a busy loop)", { since: 0, lookedAt: 20_000, now: 21_500 }, 0],
    [
      "the first look after a 20 s freeze: watching again from now",
      { since: 0, lookedAt: 20_000, now: 40_000 },
      40_000,
    ],
  ])("%s", (_, { since, lookedAt, now }, expected) => {
    expect(watchingSince(since, lookedAt, now)).toBe(expected);
  });
});

describe("a connection's clock offset", () => {
  it.each<[string, { sentAt: number; roundTripMs?: number; readAt: number }, { offsetMs: number } | null]>([
    ["no round trip measured yet: nothing known", { sentAt: 1000, readAt: 1000 }, null],
    ["same clocks, a 20 ms round trip", { sentAt: 1000, roundTripMs: 20, readAt: 1010 }, { offsetMs: 0 }],
    ["the page 5 s ahead", { sentAt: 6000, roundTripMs: 20, readAt: 1010 }, { offsetMs: 5000 }],
    ["the page 2 s behind", { sentAt: 1000, roundTripMs: 0, readAt: 3000 }, { offsetMs: -2000 }],
  ])("%s", (_, { sentAt, roundTripMs, readAt }, expected) => {
    const offset = clockOffset(sentAt, roundTripMs, readAt);
    expect(offset && { offsetMs: offset.offsetMs }).toEqual(expected);
  });
});
