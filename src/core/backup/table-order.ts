// The order a restore loads tables in: every table after the tables its
// foreign keys point at, so each row finds its parent already there (a lab's
// database user may not be allowed to switch the checks off instead).

export interface Reference {
  /** The table holding the foreign key. */
  from: string;
  /** The table it points at. */
  to: string;
}

/**
 * Parents first; among tables free to go, alphabetical, so the order is the
 * same on every run. A table pointing at itself loads in one piece (COPY checks
 * its keys at the end of the statement). A cycle between tables cannot be
 * ordered: it is refused by naming the tables in it.
 */
export function loadOrder(tables: string[], references: Reference[]): string[] {
  const known = new Set(tables);
  const parents = new Map(tables.map((t) => [t, new Set<string>()]));
  for (const { from, to } of references) {
    if (from === to || !known.has(from) || !known.has(to)) continue;
    parents.get(from)!.add(to);
  }
  const order: string[] = [];
  const placed = new Set<string>();
  while (order.length < tables.length) {
    const ready = tables.filter((t) => !placed.has(t) && [...parents.get(t)!].every((p) => placed.has(p))).sort();
    if (!ready.length) {
      const stuck = tables.filter((t) => !placed.has(t)).sort();
      throw new Error(
        `The tables ${stuck.join(", ")} point at each other in a circle; they cannot be loaded one after another.`,
      );
    }
    for (const t of ready) {
      order.push(t);
      placed.add(t);
    }
  }
  return order;
}
