// Whether events found in the log past the host's cursor are the very ones a
// command decided. An append whose reply was lost may have committed; so may
// an earlier one the wizard was told had not answered in time, landing late.
// Only the first are this command's outcome; the others are the log's truth
// to take in, and this command was not written (its seqs were taken).
import { canonicalJson } from "../protocol/canonical";
import type { EngineEvent, StoredEvent } from "./types";

/** What the engine decided, without what the log adds (seq, times, trial, actor). */
function body(event: StoredEvent): EngineEvent {
  const { seq: _seq, relMs: _relMs, trialId: _trialId, serverTime: _serverTime, actorId: _actorId, ...rest } = event;
  return rest as EngineEvent;
}

export function areTheseEvents(landed: StoredEvent[], decided: EngineEvent[]): boolean {
  return (
    landed.length === decided.length &&
    landed.every((event, i) => canonicalJson(body(event)) === canonicalJson(decided[i]))
  );
}
