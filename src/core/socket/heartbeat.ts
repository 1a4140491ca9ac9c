// The trial socket's heartbeat, both ways. A WebSocket to a frozen process
// stays open (the kernel keeps its TCP connection), so neither end learns
// from the socket that the other stopped: the page pings every
// HEARTBEAT_EVERY_MS and the runtime answers at once; a page that has heard
// nothing for RUNTIME_SILENT_AFTER_MS shows the runtime silent (within 2 s of
// its last answer), and the runtime drops a page it has not heard from for
// PAGE_GONE_AFTER_MS. The pings also carry the page's clock, from which the
// runtime keeps each connection's offset to its own. Times are injected.

export const HEARTBEAT_EVERY_MS = 500;

/** Nearly three missed answers: one late answer on a busy machine is not a silent runtime. */
export const RUNTIME_SILENT_AFTER_MS = 1400;

/** Twenty missed pings: a page frozen or gone this long is dropped (it reconnects if it comes back). */
export const PAGE_GONE_AFTER_MS = 10_000;

/** A runtime whose own look at its pages comes this late was itself stalled: it heard nothing meanwhile. */
export const STALLED_AFTER_MS = 4 * HEARTBEAT_EVERY_MS;

export type RuntimeLink = "live" | "silent";

/** The page's view of its runtime: live while it answered lately. */
export function runtimeLink(answeredAt: number, now: number): RuntimeLink {
  return now - answeredAt > RUNTIME_SILENT_AFTER_MS ? "silent" : "live";
}

/**
 * Since when the runtime has been watching its pages, given its previous look: after a stall of its own (a
 * frozen process) the pages' pings wait unread in its sockets, so their silence counts again from now.
 */
export function watchingSince(since: number, lookedAt: number, now: number): number {
  return now - lookedAt > STALLED_AFTER_MS ? now : since;
}

/** Whether the runtime drops a page it last heard from at `heardAt`, watching since `since`. */
export function pageGone(heardAt: number, since: number, now: number): boolean {
  return now - Math.max(heardAt, since) > PAGE_GONE_AFTER_MS;
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
