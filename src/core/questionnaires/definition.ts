// A questionnaire as a researcher builds it and a participant fills it in:
// sections of items, each of a kind the form knows how to show and check.
// A published version freezes this; answers point at the version shown.
import { z } from "zod";

const text = (max: number) =>
  z.string().trim().min(1, "must not be empty").max(max, `must be at most ${max} characters`);
const itemBase = { id: z.string().min(1).max(100), text: text(1000), required: z.boolean().default(false) };

export const itemSchema = z.discriminatedUnion("kind", [
  z.object({
    ...itemBase,
    kind: z.literal("likert"),
    scale: z
      .object({
        min: z.number().int().min(0).max(1),
        max: z.number().int().min(2).max(11),
        minLabel: z.string().max(100).default(""),
        maxLabel: z.string().max(100).default(""),
      })
      .refine((s) => s.max > s.min, "the scale must run upwards"),
  }),
  z.object({
    ...itemBase,
    kind: z.literal("single"),
    options: z.array(text(200)).min(2, "needs at least 2 options").max(30),
  }),
  z.object({
    ...itemBase,
    kind: z.literal("multiple"),
    options: z.array(text(200)).min(2, "needs at least 2 options").max(30),
  }),
  z.object({ ...itemBase, kind: z.literal("short_text") }),
  z.object({ ...itemBase, kind: z.literal("long_text") }),
  z.object({ ...itemBase, kind: z.literal("number"), min: z.number().optional(), max: z.number().optional() }),
  // The consent text is the item's text; agreeing records the participant's consent.
  z.object({ ...itemBase, kind: z.literal("consent"), text: text(20_000) }),
]);

export type Item = z.infer<typeof itemSchema>;
export type ItemKind = Item["kind"];

export const INSTRUMENTS = ["sus", "godspeed"] as const;
export type Instrument = (typeof INSTRUMENTS)[number];

export const definitionSchema = z
  .object({
    title: text(200),
    instructions: z.string().max(5000).default(""),
    /** A standard instrument is scored with its published method. */
    instrument: z.enum(INSTRUMENTS).nullable().default(null),
    sections: z
      .array(
        z.object({
          id: z.string().min(1).max(100),
          title: z.string().max(200).default(""),
          /** Items shown in an order drawn per participant, where the researcher allows it. */
          randomize: z.boolean().default(false),
          items: z.array(itemSchema).max(200),
        }),
      )
      .min(1, "needs at least one section")
      .max(50),
  })
  .superRefine((d, ctx) => {
    const seen = new Set<string>();
    d.sections.forEach((s, si) =>
      s.items.forEach((item, ii) => {
        if (seen.has(item.id))
          ctx.addIssue({
            code: "custom",
            path: ["sections", si, "items", ii, "id"],
            message: `"${item.id}" is used twice`,
          });
        seen.add(item.id);
      }),
    );
  });

export type Definition = z.infer<typeof definitionSchema>;

export function items(definition: Definition): Item[] {
  return definition.sections.flatMap((s) => s.items);
}
