// A study's coding scheme: the codes observers mark while a trial runs (or
// afterwards against the recording), each on one key, grouped into sets whose
// codes exclude one another (at any moment one code of a set holds, or none),
// which is what makes agreement between two observers computable per set.
// A published version freezes it; every code event points at the version used.
import { z } from "zod";
import { countedSchema } from "./counted";

const text = (max: number) =>
  z.string().trim().min(1, "must not be empty").max(max, `must be at most ${max} characters`);
const slug = z
  .string()
  .min(1, "must not be empty")
  .max(100)
  .regex(/^[a-z0-9][a-z0-9_-]*$/, "may hold only lower-case letters, digits, - and _");

/** A point event is a moment; a state lasts from a start to an end. */
export const CODE_KINDS = ["point", "state"] as const;
export type CodeKind = (typeof CODE_KINDS)[number];

export const codeSchema = z.object({
  id: slug,
  name: text(100),
  /**
   * One key on the keyboard: a letter, a digit or a punctuation mark, compared
   * without case. Space and Escape are not codes' keys.
   */
  key: z
    .string()
    .regex(/^[a-z0-9`\-=[\];',./]$/i, "must be one key: a letter, a digit or a punctuation mark")
    .transform((k) => k.toLowerCase()),
  colour: z.string().regex(/^#[0-9a-f]{6}$/i, "must be a colour like #3b82f6"),
  kind: z.enum(CODE_KINDS),
  /** Qualifiers an observer may add to one code event (e.g. "verbal", "gesture"). */
  modifiers: z.array(text(100)).max(20).default([]),
});

export const codeSetSchema = z.object({
  id: slug,
  name: text(100),
  codes: z.array(codeSchema).min(1, "needs at least one code").max(30),
});

export const schemeSchema = z
  .object({
    name: text(200),
    description: z.string().max(5000).default(""),
    sets: z.array(codeSetSchema).min(1, "needs at least one set of codes").max(20),
    /** How agreement is counted, chosen on the Results tab: the analysis's, so a published version leaves it out. */
    counted: countedSchema.optional(),
  })
  .superRefine((s, ctx) => {
    const setIds = new Set<string>();
    const keys = new Map<string, string>();
    s.sets.forEach((set, si) => {
      if (setIds.has(set.id))
        ctx.addIssue({ code: "custom", path: ["sets", si, "id"], message: `"${set.id}" is used twice` });
      setIds.add(set.id);
      const codeIds = new Set<string>();
      set.codes.forEach((code, ci) => {
        const at = ["sets", si, "codes", ci];
        if (codeIds.has(code.id))
          ctx.addIssue({ code: "custom", path: [...at, "id"], message: `"${code.id}" is used twice in this set` });
        codeIds.add(code.id);
        const taken = keys.get(code.key);
        if (taken)
          ctx.addIssue({
            code: "custom",
            path: [...at, "key"],
            message: `"${code.key}" is already the key of ${taken}`,
          });
        keys.set(code.key, code.name);
        if (new Set(code.modifiers).size !== code.modifiers.length)
          ctx.addIssue({ code: "custom", path: [...at, "modifiers"], message: "a modifier is listed twice" });
      });
    });
  });

export type Code = z.infer<typeof codeSchema>;
export type CodeSet = z.infer<typeof codeSetSchema>;
export type Scheme = z.infer<typeof schemeSchema>;

export type SchemeCheck = { ok: true; scheme: Scheme } | { ok: false; problems: string[] };

/** Every problem of a scheme, each as "where: what", for the researcher to correct. */
export function checkScheme(input: unknown): SchemeCheck {
  const parsed = schemeSchema.safeParse(input);
  if (parsed.success) return { ok: true, scheme: parsed.data };
  return { ok: false, problems: parsed.error.issues.map((i) => `${i.path.join(".") || "(scheme)"}: ${i.message}`) };
}

/** The code (and its set) a key marks, if any. */
export function codeForKey(scheme: Scheme, key: string): { set: CodeSet; code: Code } | undefined {
  const k = key.toLowerCase();
  for (const set of scheme.sets) {
    const code = set.codes.find((c) => c.key === k);
    if (code) return { set, code };
  }
  return undefined;
}

/** The code a set and code id name in a scheme, if it holds them. */
export function findCode(scheme: Scheme, setId: string, codeId: string): { set: CodeSet; code: Code } | undefined {
  const set = scheme.sets.find((s) => s.id === setId);
  const code = set?.codes.find((c) => c.id === codeId);
  return set && code ? { set, code } : undefined;
}
