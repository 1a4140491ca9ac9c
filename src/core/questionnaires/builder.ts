// The questionnaire builder as plain functions over a definition, so every
// edit a researcher makes is tested without a browser. Each returns a new
// definition and leaves the old one as it was.
import type { Definition, Item, ItemKind } from "./definition";

type NewId = () => string;

export function blankQuestionnaire(title: string, newId: NewId): Definition {
  return {
    title,
    instructions: "",
    instrument: null,
    sections: [{ id: newId(), title: "", randomize: false, items: [] }],
  };
}

/** A new item of a kind, ready to edit: a Likert item gets a 1–5 scale, a choice two options. */
export function newItem(kind: ItemKind, id: string): Item {
  const base = { id, text: "New question", required: false };
  switch (kind) {
    case "likert":
      return { ...base, kind, scale: { min: 1, max: 5, minLabel: "Strongly disagree", maxLabel: "Strongly agree" } };
    case "single":
    case "multiple":
      return { ...base, kind, options: ["Option 1", "Option 2"] };
    case "number":
      return { ...base, kind };
    case "consent":
      return {
        ...base,
        kind,
        text: "I have read the information above and agree to take part in this study.",
        required: true,
      };
    default:
      return { ...base, kind };
  }
}

const mapSections = (
  d: Definition,
  change: (s: Definition["sections"][number]) => Definition["sections"][number],
): Definition => ({ ...d, sections: d.sections.map(change) });

export const builder = {
  setDetails: (d: Definition, changes: Partial<Pick<Definition, "title" | "instructions">>): Definition => ({
    ...d,
    ...changes,
  }),

  addSection: (d: Definition, title: string, id: string): Definition => ({
    ...d,
    sections: [...d.sections, { id, title, randomize: false, items: [] }],
  }),

  updateSection: (d: Definition, sectionId: string, changes: { title?: string; randomize?: boolean }): Definition =>
    mapSections(d, (s) => (s.id === sectionId ? { ...s, ...changes } : s)),

  /** The last section cannot go: a questionnaire always has somewhere to put items. */
  removeSection: (d: Definition, sectionId: string): Definition =>
    d.sections.length > 1 ? { ...d, sections: d.sections.filter((s) => s.id !== sectionId) } : d,

  addItem: (d: Definition, sectionId: string, kind: ItemKind, id: string): Definition =>
    mapSections(d, (s) => (s.id === sectionId ? { ...s, items: [...s.items, newItem(kind, id)] } : s)),

  updateItem: (d: Definition, itemId: string, changes: Partial<Item>): Definition =>
    mapSections(d, (s) => ({
      ...s,
      items: s.items.map((i) => (i.id === itemId ? ({ ...i, ...changes, id: i.id, kind: i.kind } as Item) : i)),
    })),

  removeItem: (d: Definition, itemId: string): Definition =>
    mapSections(d, (s) => ({ ...s, items: s.items.filter((i) => i.id !== itemId) })),

  /** Up or down within its section. */
  moveItem: (d: Definition, itemId: string, delta: -1 | 1): Definition =>
    mapSections(d, (s) => {
      const from = s.items.findIndex((i) => i.id === itemId);
      const to = from + delta;
      if (from < 0 || to < 0 || to >= s.items.length) return s;
      const moved = [...s.items];
      [moved[from], moved[to]] = [moved[to]!, moved[from]!];
      return { ...s, items: moved };
    }),
};
