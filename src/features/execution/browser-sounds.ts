// Which sounds the wizard's browser must play now: each "Play audio" action
// the runtime handed to the browser (its robot cannot play a file) that has
// not ended yet. Read from the event log, like everything on this page.
import type { TrialState } from "@/core/trial";

interface LoggedEvent {
  type: string;
  actionId?: string;
  parameters?: Record<string, unknown>;
  detail?: Record<string, unknown>;
}

export interface BrowserSound {
  actionId: string;
  fileId: string;
  name: string;
  /** The emergency stop was pressed while it played: the browser silences it and says so. */
  silenced: boolean;
}

export function browserSounds(events: LoggedEvent[], state: TrialState): BrowserSound[] {
  const requested = new Map(
    events.filter((e) => e.type === "action.requested" && e.actionId).map((e) => [e.actionId!, e.parameters ?? {}]),
  );
  return events.flatMap((e, at) => {
    if (e.type !== "action.dispatched" || e.detail?.playedBy !== "browser" || !e.actionId) return [];
    if (state.actions[e.actionId]?.status !== "running") return [];
    const p = requested.get(e.actionId) ?? {};
    const silenced = events.slice(at + 1).some((later) => later.type === "trial.emergency_stop");
    return [{ actionId: e.actionId, fileId: String(p.fileId ?? ""), name: String(p.name ?? "sound"), silenced }];
  });
}
