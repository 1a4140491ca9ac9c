// Assigning participants to conditions, on the server, reproducibly: every
// strategy is a pure function of the study's seed and the participant's
// position in the assignment order, so the stored seed is the whole audit.
import { seededRandom, shuffled } from "./random";
import type { AssignmentSettings } from "./settings";

export type Strategy =
  | { kind: "fixed" }
  | { kind: "random" }
  // Each block holds every condition `perCondition` times in shuffled order,
  // so counts never differ by more than one block.
  | { kind: "balanced"; perCondition: number }
  // Within-subject: each participant gets every condition, in the order of a
  // balanced Latin square row.
  | { kind: "counterbalanced" }
  // Balanced blocks kept separately for each answer to one demographic
  // question (e.g. programming experience), so every condition gets its
  // share of each group. `stratum` is this participant's group; the position
  // counts only the participants assigned in it.
  | { kind: "stratified"; perCondition: number; stratum: string };

export type Assignment = { condition: string } | { order: string[] };

export function assign(
  strategy: Strategy,
  conditions: readonly string[],
  seed: string,
  position: number,
  fixed?: string,
): Assignment {
  if (conditions.length === 0) throw new Error("The study has no conditions to assign.");
  if (!Number.isInteger(position) || position < 0) throw new Error("position must be a whole number from 0.");
  switch (strategy.kind) {
    case "fixed":
      if (!fixed || !conditions.includes(fixed))
        throw new Error(`Choose one of the conditions: ${conditions.join(", ")}.`);
      return { condition: fixed };
    case "random":
      return { condition: conditions[Math.floor(seededRandom(`${seed}:${position}`)() * conditions.length)]! };
    case "balanced": {
      const size = conditions.length * strategy.perCondition;
      const block = Math.floor(position / size);
      const order = shuffled(
        conditions.flatMap((c) => Array<string>(strategy.perCondition).fill(c)),
        seededRandom(`${seed}:block:${block}`),
      );
      return { condition: order[position % size]! };
    }
    case "stratified":
      return assign(
        { kind: "balanced", perCondition: strategy.perCondition },
        conditions,
        `${seed}:stratum:${strategy.stratum}`,
        position,
      );
    case "counterbalanced": {
      const rows = balancedLatinSquare(conditions.length);
      return { order: rows[position % rows.length]!.map((i) => conditions[i]!) };
    }
  }
}

/**
 * Williams' balanced Latin square: every condition appears once in every
 * position, and (for an even number of conditions) follows every other
 * condition exactly once. An odd number needs the mirrored rows as well.
 */
export function balancedLatinSquare(n: number): number[][] {
  // Williams' first row is 0, 1, n-1, 2, n-2, …; each next row adds 1 (mod n).
  const base = [
    0,
    ...Array.from({ length: n - 1 }, (_, i) => (i % 2 === 0 ? Math.floor(i / 2) + 1 : n - Math.ceil(i / 2))),
  ];
  const rows = Array.from({ length: n }, (_, r) => base.map((c) => (c + r) % n));
  return n % 2 === 0 ? rows : [...rows, ...rows.map((row) => [...row].reverse())];
}

/** The group of a participant who left the stratifying question unanswered: a stratum of its own. */
export const NOT_GIVEN = "(not given)";

/** The stratum a participant's answers put them in. */
export function stratumOf(field: string, demographics: Record<string, unknown>): string {
  const answer = demographics[field];
  return answer === undefined || answer === null || answer === "" ? NOT_GIVEN : String(answer);
}

/** The strategy the study's settings apply to one participant. */
export function strategyFor(settings: AssignmentSettings, demographics: Record<string, unknown>): Strategy {
  switch (settings.strategy) {
    case "balanced":
      return { kind: "balanced", perCondition: settings.perCondition };
    case "stratified":
      return {
        kind: "stratified",
        perCondition: settings.perCondition,
        stratum: stratumOf(settings.stratifyBy ?? "", demographics),
      };
    default:
      return { kind: settings.strategy };
  }
}

/** How many participants of each stratum each condition holds: the balance a stratified study reports. */
export function strataCounts(
  assigned: ReadonlyArray<{ stratum: string | null; condition: string | null }>,
): Array<{ stratum: string; counts: Record<string, number> }> {
  const table = new Map<string, Record<string, number>>();
  for (const { stratum, condition } of assigned) {
    if (stratum === null || condition === null) continue;
    const counts = table.get(stratum) ?? {};
    counts[condition] = (counts[condition] ?? 0) + 1;
    table.set(stratum, counts);
  }
  return [...table].sort(([a], [b]) => a.localeCompare(b)).map(([stratum, counts]) => ({ stratum, counts }));
}
