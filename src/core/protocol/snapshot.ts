// The published form of an experiment: everything a trial needs to run it,
// frozen. Trials, exports and reports read this, never the live draft. A
// stored snapshot keeps the bytes it was hashed with; older schema versions are
// upgraded as they are read, so the rest of the code knows one shape.
import { draftFrom } from "../designer/model";
import { type DesignDraft, type ProtocolSnapshot, SNAPSHOT_SCHEMA_VERSION } from "./document";

export type { ProtocolSnapshot } from "./document";

/** Freezes a design (a stored one carries more: positions, times, revision) into its snapshot. */
export function snapshotOf(design: DesignDraft & { id: string }): ProtocolSnapshot {
  const { steps, ...experiment } = draftFrom(design);
  return { schemaVersion: SNAPSHOT_SCHEMA_VERSION, experiment: { id: design.id, ...experiment }, steps };
}

interface SnapshotV1 {
  schemaVersion: 1;
  experiment: { id: string; name: string; description: string; robotPluginId: string };
  steps: ProtocolSnapshot["steps"];
}

/** A snapshot as stored (any schema version so far), in today's shape. */
export function readSnapshot(stored: unknown): ProtocolSnapshot {
  const snapshot = stored as ProtocolSnapshot | SnapshotV1;
  if (snapshot.schemaVersion === SNAPSHOT_SCHEMA_VERSION) return snapshot;
  if (snapshot.schemaVersion === 1) {
    // Version 1 named the robot robotPluginId; its steps had no "after" (each went on to the next).
    const { robotPluginId, ...experiment } = snapshot.experiment;
    return {
      schemaVersion: SNAPSHOT_SCHEMA_VERSION,
      experiment: { ...experiment, robotId: robotPluginId },
      steps: snapshot.steps,
    };
  }
  throw new Error(
    `Unknown experiment snapshot schema version ${String((stored as { schemaVersion?: unknown })?.schemaVersion)}`,
  );
}
