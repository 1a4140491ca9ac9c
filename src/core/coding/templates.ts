// Ready-made coding schemes a study starts from with one click, worded as the
// studies they come from code. Each is a valid scheme (coding.test.ts checks).
import type { Scheme } from "./scheme";

export const SCHEME_TEMPLATES = ["wizard-interventions", "participant-engagement"] as const;
export type SchemeTemplate = (typeof SCHEME_TEMPLATES)[number];

const TEMPLATES: Record<SchemeTemplate, Scheme> = {
  // The intervention types published WoZ pilots code when the wizard steps in
  // beyond the script (technical, clarification, hint, guidance): one set, so
  // each intervention is exactly one type and two observers can be compared.
  "wizard-interventions": {
    name: "Wizard interventions",
    description:
      "Each time the wizard steps in beyond the script, mark the kind of intervention: a technical fix, a clarification of what was said, a hint towards the answer, or guidance through the task.",
    sets: [
      {
        id: "intervention",
        name: "Intervention type",
        codes: [
          { id: "technical", name: "Technical", key: "t", colour: "#dc2626", kind: "point", modifiers: [] },
          { id: "clarification", name: "Clarification", key: "c", colour: "#2563eb", kind: "point", modifiers: [] },
          { id: "hint", name: "Hint", key: "h", colour: "#d97706", kind: "point", modifiers: [] },
          { id: "guidance", name: "Guidance", key: "g", colour: "#16a34a", kind: "point", modifiers: [] },
        ],
      },
    ],
  },
  // The participant's visible attention and affect, as HRI observation studies
  // code them: where the gaze rests (a state) and moments of expression.
  "participant-engagement": {
    name: "Participant engagement",
    description:
      "Where the participant looks, held as a state until it moves, and moments of expression as they happen.",
    sets: [
      {
        id: "gaze",
        name: "Gaze",
        codes: [
          { id: "robot", name: "At the robot", key: "r", colour: "#7c3aed", kind: "state", modifiers: [] },
          { id: "task", name: "At the task", key: "k", colour: "#0891b2", kind: "state", modifiers: [] },
          { id: "away", name: "Away", key: "a", colour: "#64748b", kind: "state", modifiers: [] },
        ],
      },
      {
        id: "expression",
        name: "Expression",
        codes: [
          { id: "smile", name: "Smile", key: "s", colour: "#16a34a", kind: "point", modifiers: ["laugh"] },
          {
            id: "hesitation",
            name: "Hesitation",
            key: "e",
            colour: "#ea580c",
            kind: "point",
            modifiers: ["verbal", "gesture"],
          },
        ],
      },
    ],
  },
};

/** A fresh copy of a template, for a new scheme to start from. */
export const schemeTemplate = (template: SchemeTemplate): Scheme => structuredClone(TEMPLATES[template]);

/** A new scheme's first draft: one set with one code, to be renamed. */
export const blankScheme = (name: string): Scheme => ({
  name,
  description: "",
  sets: [
    {
      id: "set-1",
      name: "Codes",
      codes: [{ id: "code-1", name: "Code", key: "1", colour: "#2563eb", kind: "point", modifiers: [] }],
    },
  ],
});

const KEY_ORDER = "123456789abcdefghijklmnopqrstuvwxyz0";
const COLOURS = ["#2563eb", "#dc2626", "#16a34a", "#d97706", "#7c3aed", "#0891b2", "#db2777", "#64748b"];

/** A new code for a set of a scheme: on the first key no code of the scheme has taken. */
export function newCode(scheme: Scheme): Scheme["sets"][number]["codes"][number] {
  const codes = scheme.sets.flatMap((s) => s.codes);
  const taken = new Set(codes.map((c) => c.key));
  const ids = new Set(codes.map((c) => c.id));
  let n = codes.length + 1;
  while (ids.has(`code-${n}`)) n++;
  return {
    id: `code-${n}`,
    name: `Code ${n}`,
    key: [...KEY_ORDER].find((k) => !taken.has(k)) ?? "",
    colour: COLOURS[codes.length % COLOURS.length]!,
    kind: "point",
    modifiers: [],
  };
}
