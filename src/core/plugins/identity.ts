// Who provides a robot, and how far its plugin is trusted. A plugin document's
// identity is its source (the first-party folder or one repository), robotId,
// version and content hash: two sources may offer the same robotId, even the
// same version, and both are kept and told apart. Which one an experiment runs
// is its own choice; without one, the default is first-party first, then the
// repository that installed the robot first.
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

/** What tells one plugin document from every other. */
export interface PluginIdentity {
  /** FIRST_PARTY or a repository's id. */
  source: string;
  robotId: string;
  version: string;
  /** SHA-256 of the document's canonical JSON. */
  hash: string;
}

export interface ProvidedPlugin extends PluginIdentity {
  /** Who the source is, in words: "the first-party plugins" or the repository's name. */
  sourceName: string;
}

/** The identity as one string: equal strings, the same document. */
export function identityKey(p: PluginIdentity): string {
  return JSON.stringify([p.source, p.robotId, p.version, p.hash]);
}

/** The first 12 hex digits of a hash, enough for a person to tell two documents apart. */
export function shortHash(hash: string): string {
  return hash.slice(0, 12);
}

/** "nao6-ros2 3.0.0 from the first-party plugins (1a2b3c4d5e6f)". */
export function describeDocument(p: ProvidedPlugin): string {
  return `${p.robotId} ${p.version} from ${p.sourceName} (${shortHash(p.hash)})`;
}

/**
 * Every source's current document of every robot, from every installed
 * version in priority order (first-party, then oldest install first): a
 * source's later install replaces its earlier one; another source's never does.
 */
export function latestPerSource<T extends ProvidedPlugin>(inOrder: T[]): T[] {
  const latest = new Map<string, T>();
  for (const entry of inOrder) latest.set(JSON.stringify([entry.source, entry.robotId]), entry);
  return [...latest.values()];
}

/**
 * The document an experiment for `robotId` runs: the one of the source it
 * chose, or with no choice (null) the default, the first source in priority
 * order. A chosen source that does not offer the robot gives none, never
 * another source's document.
 */
export function chooseDocument<T extends ProvidedPlugin>(
  current: T[],
  robotId: string,
  source: string | null,
): T | undefined {
  return current.find((p) => p.robotId === robotId && (source === null || p.source === source));
}

/**
 * What a sync says about a document whose robot another source also offers,
 * in the administrator's words, or null when no other source offers it. Both
 * are kept; the notice says which one experiments get unless they choose.
 * `current` is every source's current document before the sync, in priority order.
 */
export function alsoProvided(offered: ProvidedPlugin, current: ProvidedPlugin[]): string | null {
  const others = current.filter((p) => p.robotId === offered.robotId && p.source !== offered.source);
  if (!others.length) return null;
  const sameVersion = others.some((p) => p.version === offered.version)
    ? ` with the same version, ${offered.version}`
    : "";
  const byDefault = chooseDocument(current, offered.robotId, null)!;
  const fallback =
    byDefault.source === offered.source
      ? "An experiment that has not chosen uses this repository's."
      : `An experiment that has not chosen uses ${describeDocument(byDefault)}.`;
  return `${offered.robotId} is also provided by ${others.map(describeDocument).join(" and ")}${sameVersion}: both are kept, told apart by their source and hash; this repository's is ${describeDocument(offered)}. ${fallback} The designer chooses which one an experiment uses.`;
}
