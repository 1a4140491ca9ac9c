import { describe, expect, it } from "vitest";
import { rowsInView } from "./virtual";

describe("the rows of a long list drawn for what is in view", () => {
  it.each([
    // A short list is drawn whole: the margin covers it.
    { count: 12, scrollTop: 0, from: 0, to: 12, before: 0, after: 0 },
    // At the top of 100k rows: the view (10 rows of 32 px in 320 px) and the margin below.
    { count: 100_000, scrollTop: 0, from: 0, to: 15, before: 0, after: (100_000 - 15) * 32 },
    // Scrolled to row 1,000: five rows of margin either side.
    { count: 100_000, scrollTop: 32_000, from: 995, to: 1015, before: 995 * 32, after: (100_000 - 1015) * 32 },
    // Halfway through a row: that row is in view.
    { count: 100_000, scrollTop: 32_016, from: 995, to: 1016, before: 995 * 32, after: (100_000 - 1016) * 32 },
    // At the end, and past it (overscrolled): never beyond the last row.
    { count: 100, scrollTop: 90 * 32, from: 85, to: 100, before: 85 * 32, after: 0 },
    { count: 100, scrollTop: 500 * 32, from: 100, to: 100, before: 100 * 32, after: 0 },
    { count: 0, scrollTop: 0, from: 0, to: 0, before: 0, after: 0 },
    // A negative scroll (an elastic bounce) is the top.
    { count: 100, scrollTop: -50, from: 0, to: 15, before: 0, after: 85 * 32 },
  ])("$count rows scrolled $scrollTop px: rows $from to $to", ({ count, scrollTop, from, to, before, after }) => {
    expect(rowsInView({ count, rowHeight: 32, scrollTop, viewport: 320, margin: 5 })).toEqual({
      from,
      to,
      before,
      after,
    });
  });
});
