// A standard instrument's scores and items as its publication names them: the
// sub-scales by their published names (not our code names), a composite only
// where the instrument defines one (SUS's 0–100; Godspeed has none, only its
// five sub-scales), and which items it scores reversed. The answers CSV, the
// analysis API and the results by condition show scores through this.
import type { Instrument } from "./definition";
import { GODSPEED_SUBSCALES } from "./scoring";

/** Bartneck et al. (2009): Godspeed I–V. */
const GODSPEED_NAMES = {
  anthropomorphism: "Anthropomorphism",
  animacy: "Animacy",
  likeability: "Likeability",
  perceivedIntelligence: "Perceived Intelligence",
  perceivedSafety: "Perceived Safety",
} as const satisfies Record<keyof typeof GODSPEED_SUBSCALES, string>;

/** Brooke (1996): one score, 0–100. */
export const SUS_SCORE = "SUS score";

export interface PublishedScore {
  /** The score's published name. */
  name: string;
  /** The sub-scale it is of; null for the instrument's composite. */
  subscale: string | null;
  value: number;
}

type Stored = { score?: number; subscales?: Record<string, number> } | null;

/** The scores an instrument publishes, from a response's stored score; none for a study's own questionnaire. */
export function publishedScores(instrument: Instrument | null, stored: Stored): PublishedScore[] {
  if (instrument === "sus" && stored?.score !== undefined)
    return [{ name: SUS_SCORE, subscale: null, value: stored.score }];
  if (instrument === "godspeed")
    return Object.entries(GODSPEED_NAMES)
      .filter(([key]) => stored?.subscales?.[key] !== undefined)
      .map(([key, name]) => ({ name, subscale: name, value: stored!.subscales![key]! }));
  return [];
}

/** An item's place in its instrument: its sub-scale's published name, and whether it is scored reversed. */
export function itemScoring(
  instrument: Instrument | null,
  itemId: string,
): { subscale: string | null; reverse: boolean } | null {
  const n = Number(/^(?:sus|gs)(\d+)$/.exec(itemId)?.[1]);
  // SUS: the even items are worded negatively and contribute 5 − answer.
  if (instrument === "sus" && itemId.startsWith("sus") && n >= 1 && n <= 10)
    return { subscale: null, reverse: n % 2 === 0 };
  if (instrument === "godspeed" && itemId.startsWith("gs")) {
    const key = Object.keys(GODSPEED_NAMES).find((k) => GODSPEED_SUBSCALES[k]!.includes(n));
    if (key) return { subscale: GODSPEED_NAMES[key as keyof typeof GODSPEED_NAMES], reverse: false };
  }
  return null;
}
