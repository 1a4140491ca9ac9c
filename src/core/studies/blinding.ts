// What a blind hides from whom. The policy refuses what would reveal it, and
// the server strips it from what it still sends (a wizard's trial, a session).
import type { StudyRole } from "../access/policy";
import type { StudySettings } from "./settings";

export interface Blinding {
  /** This caller must not learn a session's condition or experiment. */
  conditionsHidden: boolean;
  /** This caller must not see results (analysis, exports, fidelity) yet. */
  resultsHidden: boolean;
}

export const NOT_BLINDED: Blinding = { conditionsHidden: false, resultsHidden: false };

export function blindingFor(role: StudyRole | null, settings: StudySettings, studyStatus: string): Blinding {
  const ended = studyStatus === "completed" || studyStatus === "archived";
  return {
    conditionsHidden:
      (role === "wizard" && settings.blinding.conditionsFromWizards) ||
      (role === "observer" && settings.blinding.conditionsFromObservers),
    resultsHidden: (role === "researcher" || role === "observer") && settings.blinding.resultsUntilComplete && !ended,
  };
}

/** The name a blinded wizard sees in place of the experiment's. */
export const BLINDED_NAME = "Session (condition hidden)";

/** A trial as a blinded wizard may see it: nothing that names or points at its condition. */
export function blindTrial<
  T extends {
    experimentId?: string | null;
    experimentName?: string | null;
    versionId?: string | null;
    version?: number | null;
    protocol?: unknown;
  },
>(trial: T): T {
  const protocol = trial.protocol as
    | { experiment?: Record<string, unknown>; steps?: Array<{ actions: Array<{ variant?: string }> }> }
    | undefined;
  return {
    ...trial,
    ...("experimentId" in trial ? { experimentId: null } : {}),
    ...("experimentName" in trial ? { experimentName: BLINDED_NAME } : {}),
    ...("versionId" in trial ? { versionId: null } : {}),
    ...("version" in trial ? { version: null } : {}),
    ...(protocol?.experiment
      ? {
          protocol: {
            ...protocol,
            experiment: {
              id: "",
              name: BLINDED_NAME,
              description: "",
              robotId: protocol.experiment.robotId,
            },
            // The actions as the trial runs them, never which condition's variant each is.
            steps: protocol.steps?.map((step) => ({
              ...step,
              actions: step.actions.map(({ variant: _, ...action }) => action),
            })),
          },
        }
      : {}),
  };
}
