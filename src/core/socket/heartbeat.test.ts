import { describe, expect, it } from "vitest";
import {
  clockOffset,
  HEARTBEAT_EVERY_MS,
  keptOffset,
  PAGE_ASKED_AFTER_MS,
  PAGE_GONE_AFTER_MS,
  pageCheck,
  RUNTIME_SILENT_AFTER_MS,
  type RuntimeLink,
  runtimeLink,
  watchingSince,
  withSample,
} from "./heartbeat";

describe("the page's view of its runtime", () => {
  it.each<[string, number | null, number, RuntimeLink]>([
    ["every ping answered, a minute after the last (a hidden tab's timers)", null, 70_000, "live"],
    ["a ping just sent", 10_000, 10_000, "live"],
    ["a ping unanswered for one beat", 10_000, 10_000 + HEARTBEAT_EVERY_MS, "live"],
    ["unanswered up to the limit", 10_000, 10_000 + RUNTIME_SILENT_AFTER_MS, "live"],
    ["unanswered just past the limit", 10_000, 10_000 + RUNTIME_SILENT_AFTER_MS + 1, "silent"],
    ["frozen for 20 s", 10_000, 30_000, "silent"],
  ])("%s", (_, unansweredSince, now, link) => {
    expect(runtimeLink(unansweredSince, now)).toBe(link);
  });

  it("shows a runtime that froze right after answering silent within 2 s, pinging and looking once a beat", () => {
    // Frozen just after answering a ping: the next ping, a beat later, is the first unanswered; the page
    // looks at each beat, so the worst case is a look just before the limit passes.
    const frozeAt = 0;
    const unansweredSince = frozeAt + HEARTBEAT_EVERY_MS;
    let now = unansweredSince;
    while (runtimeLink(unansweredSince, now) === "live") now += HEARTBEAT_EVERY_MS;
    expect(now - frozeAt).toBeLessThanOrEqual(2000);
  });
});

describe("the runtime's view of its pages", () => {
  it.each<[string, { heardAt: number; since: number; now: number }, ReturnType<typeof pageCheck>]>([
    ["heard a ping ago", { heardAt: 50_000, since: 0, now: 50_500 }, "nothing"],
    ["quiet up to the asking", { heardAt: 50_000, since: 0, now: 50_000 + PAGE_ASKED_AFTER_MS }, "nothing"],
    ["quiet past it (a hidden tab): asked", { heardAt: 50_000, since: 0, now: 50_001 + PAGE_ASKED_AFTER_MS }, "ask"],
    ["silent up to the limit", { heardAt: 50_000, since: 0, now: 50_000 + PAGE_GONE_AFTER_MS }, "ask"],
    ["silent past the limit", { heardAt: 50_000, since: 0, now: 50_001 + PAGE_GONE_AFTER_MS }, "drop"],
    [
      "silent while the runtime itself was frozen: counted from its waking",
      { heardAt: 0, since: 25_000, now: 25_500 },
      "nothing",
    ],
    ["silent for the limit after the runtime woke", { heardAt: 0, since: 25_000, now: 35_001 }, "drop"],
  ])("%s", (_, { heardAt, since, now }, check) => {
    expect(pageCheck(heardAt, since, now)).toBe(check);
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

describe("the offset a connection keeps", () => {
  const at = (offsetMs: number, roundTripMs = 20) => ({ offsetMs, roundTripMs });
  it.each<[string, Array<{ offsetMs: number; roundTripMs: number } | null>, number | null]>([
    ["nothing measured", [null], null],
    ["one measurement", [at(5000)], 5000],
    // Pings that waited in a frozen runtime's socket, read at once on its waking: each looks behind by its wait.
    ["pings held up by a frozen runtime do not move it", [at(0), at(-20_000), at(-12_000), at(-500)], 0],
    ["a round trip too slow to measure anything is left out", [at(0), at(10_000, 20_000)], 0],
    ["only the recent ones count", [at(9000), ...Array.from({ length: 20 }, () => at(1000))], 1000],
  ])("%s", (_, measured, expected) => {
    const samples = measured.reduce<ReturnType<typeof withSample>>((kept, m) => withSample(kept, m), []);
    expect(keptOffset(samples)?.offsetMs ?? null).toBe(expected);
  });
});
