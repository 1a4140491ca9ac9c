// The designer's draft of an experiment: what a researcher edits before
// publishing. Branch targets are step ids (parameters.targets[optionId]);
// actions that share a parallelGroup and sit next to each other start together.

export interface DesignAction {
  id: string;
  type: string;
  name: string;
  parameters: Record<string, unknown>;
  parallelGroup: string | null;
}

export interface DesignStep {
  id: string;
  name: string;
  description: string;
  actions: DesignAction[];
}

export interface DesignDraft {
  name: string;
  description: string;
  robotPluginId: string;
  steps: DesignStep[];
}

/** Supplies fresh ids, so the model stays pure and tests stay deterministic. */
export type NewId = () => string;
