// Published scoring of standard instruments, computed the same way for the
// analysis page, the exports and the tests.

export type Scored = { ok: true; score: number; subscales?: Record<string, number> } | { ok: false; reason: string };

function checkAnswers(
  answers: readonly number[],
  count: number,
  min: number,
  max: number,
  name: string,
): string | null {
  if (answers.length !== count) return `${name} has ${count} items; ${answers.length} answers were given.`;
  const bad = answers.findIndex((a) => !Number.isInteger(a) || a < min || a > max);
  return bad >= 0 ? `${name} item ${bad + 1}: the answer must be a whole number from ${min} to ${max}.` : null;
}

/**
 * System Usability Scale (Brooke, 1996): ten items answered 1–5. Odd items
 * contribute (answer − 1), even items (5 − answer); the sum × 2.5 gives 0–100.
 */
export function scoreSus(answers: readonly number[]): Scored {
  const problem = checkAnswers(answers, 10, 1, 5, "The SUS");
  if (problem) return { ok: false, reason: problem };
  const sum = answers.reduce((total, a, i) => total + (i % 2 === 0 ? a - 1 : 5 - a), 0);
  return { ok: true, score: sum * 2.5 };
}

/**
 * Godspeed questionnaire (Bartneck et al., 2009): 24 semantic-differential
 * items answered 1–5, in five sub-scales scored as the mean of their items.
 * Items are numbered in the published order.
 */
export const GODSPEED_SUBSCALES: Record<string, number[]> = {
  anthropomorphism: [1, 2, 3, 4, 5],
  animacy: [6, 7, 8, 9, 10, 11],
  likeability: [12, 13, 14, 15, 16],
  perceivedIntelligence: [17, 18, 19, 20, 21],
  perceivedSafety: [22, 23, 24],
};

export function scoreGodspeed(answers: readonly number[]): Scored {
  const problem = checkAnswers(answers, 24, 1, 5, "Godspeed");
  if (problem) return { ok: false, reason: problem };
  const subscales = Object.fromEntries(
    Object.entries(GODSPEED_SUBSCALES).map(([name, items]) => [
      name,
      items.reduce((t, i) => t + answers[i - 1]!, 0) / items.length,
    ]),
  );
  const means = Object.values(subscales);
  return { ok: true, score: means.reduce((a, b) => a + b, 0) / means.length, subscales };
}
