// The runtime's side of the heartbeat (src/core/socket/heartbeat.ts): it
// answers each ping at once, keeps each connection's clock offset from them
// (for the command path to judge the page's times by), and drops a page it
// has not heard from for too long. Only a connection that has pinged is a
// page with a heartbeat: scripts and benchmarks that never ping are not dropped.
import {
  type ClockOffset,
  clockOffset,
  HEARTBEAT_EVERY_MS,
  PAGE_GONE_AFTER_MS,
  pageGone,
  watchingSince,
} from "@/core/socket/heartbeat";
import type { ClientMessage, ServerMessage } from "@/core/socket/messages";

export interface Pulse {
  /** When the runtime last read anything from this connection (its clock). */
  heardAt: number;
  /** Whether it has ever pinged: only then is its silence a page gone. */
  pinged: boolean;
  /** The page's clock against the runtime's, from its latest ping that measured one; null until then. */
  clock: ClockOffset | null;
}

export const newPulse = (now = Date.now()): Pulse => ({ heardAt: now, pinged: false, clock: null });

/** Anything read from the connection: it is alive. */
export function heard(pulse: Pulse, now = Date.now()) {
  pulse.heardAt = now;
}

/** A ping: its offset kept, its answer returned to send at once. */
export function answer(pulse: Pulse, ping: Extract<ClientMessage, { type: "ping" }>, now = Date.now()): ServerMessage {
  pulse.pinged = true;
  pulse.clock = clockOffset(ping.at, ping.roundTripMs, now) ?? pulse.clock;
  return { type: "pong", at: ping.at };
}

const GONE_REASON = `This page sent nothing for ${PAGE_GONE_AFTER_MS / 1000} s, so its connection was closed.`;

/**
 * Looks at the pages every heartbeat, for as long as the process runs, and drops (`drop`, with a reason) those
 * gone silent. The look is a timer, so after a freeze of the runtime itself it comes late: their silence counts
 * from then.
 */
export function watchPulses(
  pages: () => Iterable<{ pulse: Pulse; drop: (reason: string) => void }>,
  now = () => Date.now(),
): void {
  let since = now();
  let lookedAt = since;
  const timer = setInterval(() => {
    const at = now();
    since = watchingSince(since, lookedAt, at);
    lookedAt = at;
    for (const { pulse, drop } of pages()) if (pulse.pinged && pageGone(pulse.heardAt, since, at)) drop(GONE_REASON);
  }, HEARTBEAT_EVERY_MS);
  // Never what keeps the process alive: it ends with the server.
  timer.unref();
}
