import { describe, expect, it } from "vitest";
import type { Instrument } from "./definition";
import { itemScoring, publishedScores } from "./published-scores";
import { scoreGodspeed } from "./scoring";

const godspeed = scoreGodspeed([
  ...Array(5).fill(2),
  ...Array(6).fill(3),
  ...Array(5).fill(4),
  ...Array(5).fill(5),
  1,
  2,
  3,
]);

describe("an instrument's published scores", () => {
  it.each<[string, Instrument | null, Parameters<typeof publishedScores>[1], unknown]>([
    ["SUS: its one 0–100 score", "sus", { score: 72.5 }, [{ name: "SUS score", subscale: null, value: 72.5 }]],
    [
      "Godspeed: the five sub-scales by their published names, no overall score",
      "godspeed",
      godspeed.ok ? godspeed : null,
      [
        { name: "Anthropomorphism", subscale: "Anthropomorphism", value: 2 },
        { name: "Animacy", subscale: "Animacy", value: 3 },
        { name: "Likeability", subscale: "Likeability", value: 4 },
        { name: "Perceived Intelligence", subscale: "Perceived Intelligence", value: 5 },
        { name: "Perceived Safety", subscale: "Perceived Safety", value: 2 },
      ],
    ],
    ["a study's own questionnaire: none", null, { score: 3 }, []],
    ["no stored score: none", "sus", null, []],
  ])("%s", (_, instrument, stored, scores) => expect(publishedScores(instrument, stored)).toEqual(scores));
});

describe("an item's place in its instrument", () => {
  it.each<[Instrument | null, string, unknown]>([
    ["sus", "sus1", { subscale: null, reverse: false }],
    ["sus", "sus2", { subscale: null, reverse: true }],
    ["sus", "sus10", { subscale: null, reverse: true }],
    ["sus", "sus11", null],
    ["godspeed", "gs1", { subscale: "Anthropomorphism", reverse: false }],
    ["godspeed", "gs11", { subscale: "Animacy", reverse: false }],
    ["godspeed", "gs22", { subscale: "Perceived Safety", reverse: false }],
    ["godspeed", "gs25", null],
    ["godspeed", "comments", null],
    [null, "sus2", null],
  ])("%s %s → %j", (instrument, itemId, place) => expect(itemScoring(instrument, itemId)).toEqual(place));
});
