// What the wizard's page still has to say about the trial. A refusal ("Wait:
// the 3 s pause is still running.") is about the trial as it was when the
// server refused: it stays while the engine would still refuse that command
// for that reason, and goes once the cause has ended (the pause is over, the
// trial moved to another step or ended). A refusal the engine did not make
// (who may run the trial) lasts until anything happens in the trial. An ended
// trial's controls are all off, with one plain reason; so are they while the
// page is not connected to the trial runtime, or the runtime is not answering.
import type { RuntimeState } from "./connections";
import { decide } from "./decide";
import type { Command, TrialProtocol, TrialState } from "./types";

export interface Refusal {
  reason: string;
  /** The command that was refused, when the page knows it. */
  command: Command | null;
  /** The last event of the trial the page held when the refusal came. */
  atSeq: number;
}

/** The refusal if it still describes the trial now, else null. */
export function refusalInForce(refusal: Refusal | null, protocol: TrialProtocol, state: TrialState): Refusal | null {
  if (refusal === null) return null;
  if (refusal.atSeq === state.lastSeq) return refusal;
  if (refusal.command === null) return null;
  const now = decide(protocol, state, refusal.command);
  return !now.ok && now.reason === refusal.reason ? refusal : null;
}

/**
 * Why none of the wizard's controls work, emergency stop included; null while
 * the trial can be commanded. Without the runtime nothing reaches the trial.
 */
export function controlsOffBecause(state: TrialState, runtime: RuntimeState = "live"): string | null {
  if (state.status === "completed")
    return "This trial is completed: nothing more can be sent to it or to its robot. Its record is in the analysis.";
  if (state.status === "aborted")
    return "This trial was aborted: nothing more can be sent to it or to its robot. Its record is in the analysis.";
  if (runtime === "reconnecting")
    return "The trial runtime is not connected: nothing can be sent to the trial or its robot until the page has reconnected.";
  if (runtime === "silent")
    return "The trial runtime is not answering: nothing can be sent to the trial or its robot until it answers again.";
  return null;
}
