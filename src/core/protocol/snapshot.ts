// The published form of an experiment: everything a trial needs to run it,
// frozen. Trials, exports and reports read this, never the live draft.
export const SNAPSHOT_SCHEMA_VERSION = 1;

export interface ProtocolSnapshot {
  schemaVersion: number;
  experiment: { id: string; name: string; description: string; robotPluginId: string };
  steps: Array<{
    id: string;
    name: string;
    description: string;
    actions: Array<{ id: string; type: string; name: string; parameters: Record<string, unknown>; parallelGroup: string | null }>;
  }>;
}
