// The published form of an experiment: everything a trial needs to run it,
// frozen. Trials, exports and reports read this, never the live draft.
import { draftFrom } from "@/core/designer/model";
import type { DesignDraft, DesignStep } from "@/core/designer/types";

export const SNAPSHOT_SCHEMA_VERSION = 1;

/** The draft's own fields (see DesignDraft), under the experiment's id and the schema version. */
export interface ProtocolSnapshot {
  schemaVersion: number;
  experiment: Omit<DesignDraft, "steps"> & { id: string };
  steps: DesignStep[];
}

/** Freezes a design (a stored one carries more: positions, times, revision) into its snapshot. */
export function snapshotOf(design: DesignDraft & { id: string }): ProtocolSnapshot {
  const { steps, ...experiment } = draftFrom(design);
  return { schemaVersion: SNAPSHOT_SCHEMA_VERSION, experiment: { id: design.id, ...experiment }, steps };
}
