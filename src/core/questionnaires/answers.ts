// Checking a participant's answers against the version they were shown,
// drawing the item order they see, and scoring a standard instrument.
import { seededRandom, shuffled } from "../studies/random";
import { items, type Definition, type Item } from "./definition";
import { scoreGodspeed, scoreSus, type Scored } from "./scoring";

export type Answer = number | string | string[] | boolean;
export type Answers = Record<string, Answer>;

function problemWith(item: Item, value: Answer): string | null {
  switch (item.kind) {
    case "likert":
      return Number.isInteger(value) && (value as number) >= item.scale.min && (value as number) <= item.scale.max
        ? null
        : `choose a point from ${item.scale.min} to ${item.scale.max}`;
    case "single":
      return typeof value === "string" && item.options.includes(value) ? null : "choose one of the options";
    case "multiple":
      return Array.isArray(value) &&
        value.every((v) => item.options.includes(v)) &&
        new Set(value).size === value.length
        ? null
        : "choose among the options";
    case "short_text":
    case "long_text":
      return typeof value === "string" && value.length <= (item.kind === "short_text" ? 500 : 10_000)
        ? null
        : "is too long";
    case "number":
      if (typeof value !== "number" || !Number.isFinite(value)) return "must be a number";
      if (item.min !== undefined && value < item.min) return `must be at least ${item.min}`;
      return item.max !== undefined && value > item.max ? `must be at most ${item.max}` : null;
    case "consent":
      return typeof value === "boolean" ? null : "must be agreed or not";
  }
}

const isEmpty = (v: Answer | undefined) =>
  v === undefined || v === "" || (Array.isArray(v) && v.length === 0) || v === false;

/**
 * Problems as "item: reason". A draft may be incomplete; a final answer set
 * must answer every required item (and agree to a required consent).
 */
export function answerProblems(definition: Definition, answers: Answers, final: boolean): string[] {
  const known = new Map(items(definition).map((i) => [i.id, i]));
  const problems = Object.keys(answers)
    .filter((id) => !known.has(id))
    .map((id) => `${id}: is not an item of this questionnaire`);
  for (const item of known.values()) {
    const value = answers[item.id];
    if (isEmpty(value)) {
      if (final && item.required)
        problems.push(
          `${item.text.slice(0, 80)}: ${item.kind === "consent" ? "please agree to take part, or leave the study" : "please answer"}`,
        );
      continue;
    }
    const problem = problemWith(item, value!);
    if (problem) problems.push(`${item.text.slice(0, 80)}: ${problem}`);
  }
  return problems;
}

/** The order a participant sees: sections in place, a randomised section's items shuffled from a per-link seed. */
export function presentedOrder(definition: Definition, seed: string): Definition {
  return {
    ...definition,
    sections: definition.sections.map((s) =>
      s.randomize ? { ...s, items: shuffled(s.items, seededRandom(`${seed}:${s.id}`)) } : s,
    ),
  };
}

/** The instrument's published score, when the questionnaire is one and every item is answered. */
export function scoreAnswers(definition: Definition, answers: Answers): Scored | null {
  if (!definition.instrument) return null;
  const values = items(definition).map((i) => answers[i.id] as number);
  return definition.instrument === "sus" ? scoreSus(values) : scoreGodspeed(values);
}

/** Whether a final answer set agrees to the questionnaire's consent item(s). */
export function consentGiven(definition: Definition, answers: Answers): boolean | null {
  const consent = items(definition).filter((i) => i.kind === "consent");
  return consent.length ? consent.every((i) => answers[i.id] === true) : null;
}
