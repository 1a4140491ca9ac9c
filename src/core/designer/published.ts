// Whether the draft is exactly what was last published, on the same plugin
// document: then publishing again would only make a copy, and the designer
// says so instead of offering it. Another document (the experiment chose
// another source, or a sync brought a newer version) is worth a new version.
import type { ProtocolSnapshot } from "../protocol/snapshot";
import { same } from "./diff";
import { draftFrom } from "./draft";
import type { DesignDraft } from "./types";

export interface PublishedVersion {
  version: number;
  snapshot: ProtocolSnapshot;
  /** The plugin document it pinned; null for a version from before pinning. */
  pluginHash?: string | null;
}

/**
 * The latest version's number when the draft equals it and would run the
 * same plugin document (`pluginHash`: the one the draft runs now, undefined
 * while not known), else null.
 */
export function unchangedSince(
  draft: DesignDraft,
  latest: PublishedVersion | null,
  pluginHash?: string,
): number | null {
  if (!latest) return null;
  if (latest.pluginHash && pluginHash && latest.pluginHash !== pluginHash) return null;
  const published = draftFrom({ ...latest.snapshot.experiment, steps: latest.snapshot.steps });
  return same(draftFrom(draft), published) ? latest.version : null;
}
