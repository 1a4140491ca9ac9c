// The library as the researcher reads it: one entry per capability. A robot's
// own action that carries out an abstract block ("Yes (Nod)" on NAO6 for
// "Nod") is listed under that block as one of its variants, so the library
// never shows two look-alikes with no hint which to use.
import { parseActionType, type Plugin } from "../plugins";
import { type Block, library } from "./blocks";

export interface LibraryEntry {
  block: Block;
  /** This robot's own actions that do what the block does, in the plugin's order. */
  variants: Block[];
}

export function libraryEntries(plugin: Plugin | null): LibraryEntry[] {
  const blocks = library(plugin);
  const entries: LibraryEntry[] = [];
  const byType = new Map<string, LibraryEntry>();
  const byName = new Map<string, LibraryEntry>();
  const implementing = plugin ? implementers(plugin) : new Map<string, string>();
  for (const block of blocks) {
    const parsed = parseActionType(block.type);
    if (parsed.kind === "robot") {
      const abstract = implementing.get(parsed.actionId);
      // An action that only looks like a block ("Stop" beside "Stop") is still that block's variant.
      const owner = (abstract && byType.get(abstract)) ?? byName.get(nameKey(block));
      if (owner) {
        owner.variants.push(block);
        continue;
      }
    }
    const entry = { block, variants: [] };
    entries.push(entry);
    byType.set(block.type, entry);
    if (!byName.has(nameKey(block))) byName.set(nameKey(block), entry);
  }
  return entries;
}

/**
 * Each robot action that carries out exactly one abstract action, with that
 * action's id. One that carries out several (a simulator's "Gesture" for
 * wave, nod and head shake) is a capability of its own.
 */
function implementers(plugin: Plugin): Map<string, string> {
  const found = new Map<string, Set<string>>();
  for (const [abstract, value] of Object.entries(plugin.abstract ?? {})) {
    for (const binding of Array.isArray(value) ? value : [value])
      (found.get(binding.action) ?? found.set(binding.action, new Set()).get(binding.action)!).add(abstract);
  }
  return new Map([...found].filter(([, ids]) => ids.size === 1).map(([action, ids]) => [action, [...ids][0]!]));
}

function nameKey(block: Block): string {
  return block.name.trim().toLowerCase();
}

/** The entries a search shows: a block that matches keeps all its variants; a matching variant shows its block. */
export function searchLibrary(entries: LibraryEntry[], query: string): Array<LibraryEntry & { open: boolean }> {
  const q = query.trim().toLowerCase();
  if (!q) return entries.map((e) => ({ ...e, open: false }));
  const matches = (b: Block) =>
    b.name.toLowerCase().includes(q) || b.type.toLowerCase().includes(q) || b.description.toLowerCase().includes(q);
  return entries.flatMap((entry) => {
    if (matches(entry.block)) return [{ ...entry, open: entry.variants.some(matches) }];
    const variants = entry.variants.filter(matches);
    return variants.length ? [{ block: entry.block, variants, open: true }] : [];
  });
}
