// Who provides a robot, and how far its plugin is trusted. A plugin version is
// identified by its source (the first-party folder or one repository), robotId,
// version and content hash. A robotId belongs to one source: first-party
// first, then the repository that installed it first. Another repository's
// copy never replaces it, whatever that repository says about itself.
import type { TrustLevel } from "./types";

/** The source of the plugins shipped in plugins/, where a repository's id would be. */
export const FIRST_PARTY = "first-party";

const TRUST_ORDER: TrustLevel[] = ["community", "verified", "official"];

/** The lower of two trust levels: a plugin is trusted no more than where it came from. A missing claim counts as community. */
export function effectiveTrust(
  repositoryTrust: TrustLevel | undefined,
  pluginTrust: TrustLevel | undefined,
): TrustLevel {
  const rank = (t: TrustLevel | undefined) => (t ? TRUST_ORDER.indexOf(t) : 0);
  return TRUST_ORDER[Math.min(rank(repositoryTrust), rank(pluginTrust))]!;
}

export interface ProvidedPlugin {
  robotId: string;
  /** FIRST_PARTY or a repository's id. */
  source: string;
  /** Who that is, in words: "the first-party plugins" or the repository's name. */
  sourceName: string;
}

/**
 * The plugin each robot runs with, from every installed version in priority
 * order (first-party, then oldest install first): the first source to offer a
 * robotId owns it, and its latest version in that order is the one used.
 */
export function chooseProviders<T extends ProvidedPlugin>(inOrder: T[]): T[] {
  const chosen = new Map<string, T>();
  for (const entry of inOrder) {
    const owner = chosen.get(entry.robotId);
    if (!owner || owner.source === entry.source) chosen.set(entry.robotId, entry);
  }
  return [...chosen.values()];
}

/** Why `source` may not install `robotId`, in the administrator's words, or null when it may. */
export function shadowing(robotId: string, source: string, owners: ProvidedPlugin[]): string | null {
  const owner = owners.find((o) => o.robotId === robotId);
  if (!owner || owner.source === source) return null;
  return `${robotId} is already provided by ${owner.sourceName}; this repository's copy was not installed.`;
}
