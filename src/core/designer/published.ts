// Whether the draft is exactly what was last published: then publishing again
// would only make a copy, and the designer says so instead of offering it.
import type { ProtocolSnapshot } from "../protocol/snapshot";
import { same } from "./diff";
import { draftFrom } from "./model";
import type { DesignDraft } from "./types";

export interface PublishedVersion {
  version: number;
  snapshot: ProtocolSnapshot;
}

/** The latest version's number when the draft equals it, else null. */
export function unchangedSince(draft: DesignDraft, latest: PublishedVersion | null): number | null {
  if (!latest) return null;
  const published = draftFrom({ ...latest.snapshot.experiment, steps: latest.snapshot.steps });
  return same(draftFrom(draft), published) ? latest.version : null;
}
