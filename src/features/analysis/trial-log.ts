// A trial's log for the analysis page, from its own route rather than the
// tRPC batch: a long log (100k events, ~11 MB) is sent as the server reads it,
// and the page's other reads (the trial, its annotations) come without it.
import type { TrialEvent } from "@/core/trial";

const CUT_OFF =
  "The trial's log stopped loading part-way (the connection or the server failed while sending it). Reload the page to try again.";

/** Every event of the trial as the fold reads it, or an Error with the server's own sentence. */
export async function fetchTrialLog(trialId: string): Promise<TrialEvent[]> {
  const res = await fetch(`/api/trials/${encodeURIComponent(trialId)}/events`);
  if (!res.ok) throw new Error((await res.text()) || `The trial's log could not be loaded (HTTP ${res.status}).`);
  // A log the server could not finish is cut off, never shorter JSON: said plainly, not as a parser's error.
  return (await res.json().catch(() => Promise.reject(new Error(CUT_OFF)))) as TrialEvent[];
}
