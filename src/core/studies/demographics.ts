// Checking a participant's demographic answers against the fields the study
// defines. Every field is optional (participants may decline to answer);
// what is given must fit the field.
import type { DemographicField } from "./settings";

export type Answers = Record<string, string | number>;

/** Problems as "field: reason", empty when the answers fit. */
export function demographicProblems(fields: DemographicField[], answers: Answers): string[] {
  const problems: string[] = [];
  for (const [key, value] of Object.entries(answers)) {
    const field = fields.find((f) => f.key === key);
    if (!field) {
      problems.push(`${key}: is not a demographic field of this study`);
    } else if (field.type === "number" && (typeof value !== "number" || !Number.isFinite(value))) {
      problems.push(`${field.label}: must be a number`);
    } else if (field.type === "choice" && !field.options.includes(String(value))) {
      problems.push(`${field.label}: must be one of ${field.options.join(", ")}`);
    } else if (field.type === "text" && (typeof value !== "string" || value.length > 200)) {
      problems.push(`${field.label}: must be text of at most 200 characters`);
    }
  }
  return problems;
}
