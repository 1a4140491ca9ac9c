// Looks through a caller's input as sent, before any schema has dropped or
// reshaped it: what it names, and what no stored text may hold.

export interface Named {
  /** Where in the input, as a person reads it: "steps.0.actions.1.id". */
  path: string;
  key: string;
  value: unknown;
}

const MAX_DEPTH = 12;

/** Every value held under one of `keys`, at any depth (arrays and objects). */
export function namedIn(input: unknown, keys: ReadonlySet<string>): Named[] {
  const found: Named[] = [];
  visit(input, "", 0, (path, key, value) => {
    if (keys.has(key)) found.push({ path, key, value });
  });
  return found;
}

/** The first text holding a NUL character, which PostgreSQL cannot store: its path, or null. */
export function nulPath(input: unknown): string | null {
  let hit: string | null = null;
  const check = (path: string, text: string) => {
    // The path itself may hold the NUL (in a field name): show it, never send it back.
    if (hit === null && text.includes("\u0000")) hit = path.replaceAll("\u0000", "\\0") || "(input)";
  };
  visit(input, "", 0, (path, key, value) => {
    check(path, key);
    if (typeof value === "string") check(path, value);
  });
  if (typeof input === "string") check("", input);
  return hit;
}

/** What a caller is told of a NUL at `path`: the same sentence from the API and from every route. */
export const nulRefusal = (path: string) => `Please correct: ${path}: must not contain the NUL character (\\0)`;

function visit(value: unknown, path: string, depth: number, see: (path: string, key: string, value: unknown) => void) {
  if (depth > MAX_DEPTH || value === null || typeof value !== "object") return;
  const entries = Array.isArray(value) ? value.map((v, i) => [String(i), v] as const) : Object.entries(value);
  for (const [key, child] of entries) {
    const childPath = path ? `${path}.${key}` : key;
    see(childPath, key, child);
    visit(child, childPath, depth + 1, see);
  }
}
