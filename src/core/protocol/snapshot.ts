// The published form of an experiment: everything a trial needs to run it,
// frozen. Trials, exports and reports read this, never the live draft. A
// stored snapshot keeps the bytes it was hashed with; older versions are
// upgraded as they are read (./versions.ts), so the rest of the code knows one shape.
import { draftFrom } from "../designer/draft";
import { type DesignDraft, DOCUMENT_VERSION, type ProtocolSnapshot } from "./document";

export type { ProtocolSnapshot } from "./document";
export { readSnapshot } from "./versions";

/** Freezes a design (a stored one carries more: positions, times, revision) into its snapshot. */
export function snapshotOf(design: DesignDraft & { id: string }): ProtocolSnapshot {
  const { steps, ...experiment } = draftFrom(design);
  return { schemaVersion: DOCUMENT_VERSION, experiment: { id: design.id, ...experiment }, steps };
}
