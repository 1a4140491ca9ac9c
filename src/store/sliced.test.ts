import { describe, expect, it } from "vitest";
import type { Work } from "@/core/work";
import { sliced } from "./sliced";

/** Work of `pieces` pieces, each busy for a millisecond, noting whether `other` had run when it ended. */
function* busy(pieces: number, seen: { other: boolean }): Work<boolean> {
  for (let i = 0; i < pieces; i++) {
    const until = performance.now() + 1;
    while (performance.now() < until);
    yield;
  }
  return seen.other;
}

describe("work run in slices", () => {
  it("lets what else is waiting run before it ends, and gives its result", async () => {
    const seen = { other: false };
    setImmediate(() => {
      seen.other = true;
    });
    expect(await sliced(busy(50, seen))).toBe(true);
  });

  it.each([0, 1, 1000])("gives the result of work that yields %i times", async (times) => {
    function* counting(): Work<number> {
      for (let i = 0; i < times; i++) yield;
      return times;
    }
    expect(await sliced(counting())).toBe(times);
  });
});
