import { describe, expect, it } from "vitest";
import { scoreGodspeed, scoreSus } from "./scoring";

describe("SUS", () => {
  it.each<[number[], number]>([
    // Worked by hand: odd items 3+2+2+2+2 = 11, even items 3+1+4+2+3 = 13; 24 × 2.5.
    [[4, 2, 3, 4, 3, 1, 3, 3, 3, 2], 60],
    [[5, 1, 5, 1, 5, 1, 5, 1, 5, 1], 100],
    [[1, 5, 1, 5, 1, 5, 1, 5, 1, 5], 0],
    [[3, 3, 3, 3, 3, 3, 3, 3, 3, 3], 50],
  ])("%j scores %d", (answers, score) => {
    expect(scoreSus(answers)).toEqual({ ok: true, score });
  });

  it.each<[number[], string]>([
    [[4, 2, 3], "The SUS has 10 items; 3 answers were given."],
    [[4, 2, 3, 4, 6, 1, 3, 3, 3, 2], "The SUS item 5: the answer must be a whole number from 1 to 5."],
    [[4, 2, 3, 4, 3, 1.5, 3, 3, 3, 2], "The SUS item 6: the answer must be a whole number from 1 to 5."],
  ])("refuses %j", (answers, reason) => {
    expect(scoreSus(answers)).toEqual({ ok: false, reason });
  });
});

describe("Godspeed", () => {
  it("scores each sub-scale as the mean of its items", () => {
    const answers = [...Array(5).fill(2), ...Array(6).fill(3), ...Array(5).fill(4), ...Array(5).fill(5), 1, 2, 3];
    expect(scoreGodspeed(answers)).toEqual({
      ok: true,
      score: (2 + 3 + 4 + 5 + 2) / 5,
      subscales: { anthropomorphism: 2, animacy: 3, likeability: 4, perceivedIntelligence: 5, perceivedSafety: 2 },
    });
  });

  it("refuses a short answer list", () => {
    expect(scoreGodspeed([1, 2])).toEqual({ ok: false, reason: "Godspeed has 24 items; 2 answers were given." });
  });
});
