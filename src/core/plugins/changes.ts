// What a repository sync changed, for the administrator to review: plugins
// added, removed or updated (with their versions), and which actions changed.
import { canonicalJson } from "../protocol/canonical";
import type { Plugin } from "./types";

export interface PluginChange {
  robotId: string;
  change: "added" | "removed" | "updated" | "unchanged";
  fromVersion?: string;
  toVersion?: string;
  actions: { added: string[]; removed: string[]; changed: string[] };
}

export function pluginChanges(before: Plugin[], after: Plugin[]): PluginChange[] {
  const old = new Map(before.map((p) => [p.robotId, p]));
  const now = new Map(after.map((p) => [p.robotId, p]));
  const ids = [...new Set([...old.keys(), ...now.keys()])].sort();
  return ids.map((robotId) => {
    const a = old.get(robotId);
    const b = now.get(robotId);
    const actions = actionChanges(a, b);
    const change = !a ? "added" : !b ? "removed" : canonicalJson(a) === canonicalJson(b) ? "unchanged" : "updated";
    return { robotId, change, fromVersion: a?.version, toVersion: b?.version, actions };
  });
}

function actionChanges(a: Plugin | undefined, b: Plugin | undefined) {
  const old = new Map((a?.actions ?? []).map((x) => [x.id, canonicalJson(x)]));
  const now = new Map((b?.actions ?? []).map((x) => [x.id, canonicalJson(x)]));
  return {
    added: [...now.keys()].filter((id) => !old.has(id)),
    removed: [...old.keys()].filter((id) => !now.has(id)),
    changed: [...now.keys()].filter((id) => old.has(id) && old.get(id) !== now.get(id)),
  };
}

/**
 * What a sync says of a robot its repository no longer lists: gone from new
 * experiments, still run where a version pinned it, and who still uses it.
 */
export function removedNotice(robotId: string, repositoryName: string, usedBy: string[]): string {
  const users = usedBy.length
    ? ` Experiments still using it: ${usedBy.join(", ")}; they keep their published versions, and a new version needs another plugin of ${robotId}.`
    : " No experiment uses it.";
  return `${robotId} is no longer listed by ${repositoryName}: it is not offered for new experiments any more. Versions published with it keep running with the document they pinned.${users}`;
}

/** What a sync that could not read every file of the index says of the robots it did not see: kept, not removed. */
export function notSeenNotice(robotIds: string[]): string {
  return `${robotIds.join(", ")} ${robotIds.length > 1 ? "were" : "was"} not among the plugins read this time, as not every file of the repository could be read: kept as before until a sync reads them all.`;
}
