// The trial socket's heartbeat, both ways. A WebSocket to a frozen process
// stays open (the kernel keeps its TCP connection), so neither end learns
// from the socket that the other stopped: the page pings every
// HEARTBEAT_EVERY_MS and the runtime answers at once; a page whose ping has
// gone unanswered for RUNTIME_SILENT_AFTER_MS shows the runtime silent
// (within 2 s of its freezing). The runtime asks a page it has not heard from
// lately (a hidden tab's timers may run once a minute, its message handlers
// at once), and drops one that answers nothing for PAGE_GONE_AFTER_MS. The
// pings also carry the page's clock, from which the runtime keeps each
// connection's offset to its own. Times are injected.

export const HEARTBEAT_EVERY_MS = 500;

/** Nearly three missed answers: one late answer on a busy machine is not a silent runtime. */
export const RUNTIME_SILENT_AFTER_MS = 1400;

/** A page quiet this long is asked whether it is there (its own timers may be held back while it is hidden). */
export const PAGE_ASKED_AFTER_MS = 2000;

/** Twenty missed pings, and the runtime's own asking unanswered: a page frozen or gone this long is dropped. */
export const PAGE_GONE_AFTER_MS = 10_000;

/** A runtime whose own look at its pages comes this late was itself stalled: it heard nothing meanwhile. */
export const STALLED_AFTER_MS = 4 * HEARTBEAT_EVERY_MS;

export type RuntimeLink = "live" | "silent";

/**
 * The page's view of its runtime, from its oldest ping that nothing has answered since (null: none).
 * Judged from an unanswered ping, not from the last answer: a page whose own timers were held back (a
 * hidden tab) has not been waiting for an answer meanwhile.
 */
export function runtimeLink(unansweredSince: number | null, now: number): RuntimeLink {
  return unansweredSince !== null && now - unansweredSince > RUNTIME_SILENT_AFTER_MS ? "silent" : "live";
}

/**
 * Since when the runtime has been watching its pages, given its previous look: after a stall of its own (a
 * frozen process) the pages' pings wait unread in its sockets, so their silence counts again from now.
 */
export function watchingSince(since: number, lookedAt: number, now: number): number {
  return now - lookedAt > STALLED_AFTER_MS ? now : since;
}

/** What the runtime does about a page it last heard from at `heardAt`, watching since `since`. */
export function pageCheck(heardAt: number, since: number, now: number): "nothing" | "ask" | "drop" {
  const quiet = now - Math.max(heardAt, since);
  return quiet > PAGE_GONE_AFTER_MS ? "drop" : quiet > PAGE_ASKED_AFTER_MS ? "ask" : "nothing";
}

/** How far a page's clock is ahead of the runtime's (negative: behind), as one ping measured it. */
export interface ClockOffset {
  offsetMs: number;
  /** The round trip the page last measured: the offset is known to within half of it. */
  roundTripMs: number;
}

/**
 * The offset from one ping sent at page time `sentAt` and read at runtime time `readAt`: it travelled about
 * half the page's last round trip. A ping without a round trip yet measures nothing (null).
 */
export function clockOffset(sentAt: number, roundTripMs: number | undefined, readAt: number): ClockOffset | null {
  if (roundTripMs === undefined) return null;
  return { offsetMs: Math.round(sentAt + roundTripMs / 2 - readAt), roundTripMs };
}

/** A round trip slower than this measures no clock: the ping may have waited anywhere on its way. */
export const CLOCK_ROUND_TRIP_MAX_MS = 1000;

/** How many recent measurements the offset is judged from: ten seconds of pings. */
export const CLOCK_SAMPLES = 20;

/**
 * The recent measurements (newest last) with one more, as the offset is judged from: a round trip too slow
 * to tell anything is left out, and only the last CLOCK_SAMPLES are kept.
 */
export function withSample(samples: readonly ClockOffset[], next: ClockOffset | null): ClockOffset[] {
  if (!next || next.roundTripMs > CLOCK_ROUND_TRIP_MAX_MS) return [...samples];
  return [...samples, next].slice(-CLOCK_SAMPLES);
}

/**
 * The connection's offset: the largest of the recent measurements. A ping that waited on its way (in the
 * socket of a frozen runtime) is read late and measures the page's clock too far behind, and none measures
 * it ahead by more than half its round trip: the largest is the least delayed.
 */
export function keptOffset(samples: readonly ClockOffset[]): ClockOffset | null {
  return samples.reduce<ClockOffset | null>(
    (best, s) => (best === null || s.offsetMs > best.offsetMs ? s : best),
    null,
  );
}
