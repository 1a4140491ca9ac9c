// The runtime's side of the heartbeat (src/core/socket/heartbeat.ts): it
// answers each ping at once, keeps each connection's clock offset from them
// (for the command path to judge the page's times by), asks a page it has not
// heard from lately, and drops one that stays silent. Only a connection that
// has pinged is a page with a heartbeat: scripts and benchmarks that never
// ping are neither asked nor dropped.
import {
  type ClockOffset,
  clockOffset,
  HEARTBEAT_EVERY_MS,
  keptOffset,
  PAGE_GONE_AFTER_MS,
  pageCheck,
  watchingSince,
  withSample,
} from "@/core/socket/heartbeat";
import type { ClientMessage, ServerMessage } from "@/core/socket/messages";

export interface Pulse {
  /** When the runtime last read anything from this connection (its clock). */
  heardAt: number;
  /** Whether it has ever pinged: only then is its silence a page gone. */
  pinged: boolean;
  /** The page's clock against the runtime's, judged from its recent pings (keptOffset); null until one measured it. */
  clock: ClockOffset | null;
  /** Those recent measurements, newest last. */
  clocks: ClockOffset[];
}

export const newPulse = (): Pulse => ({ heardAt: Date.now(), pinged: false, clock: null, clocks: [] });

/** Anything read from the connection: it is alive. */
export function heard(pulse: Pulse) {
  pulse.heardAt = Date.now();
}

/** A ping: its offset kept, its answer returned to send at once. */
export function answer(pulse: Pulse, ping: Extract<ClientMessage, { type: "ping" }>): ServerMessage {
  pulse.pinged = true;
  pulse.clocks = withSample(pulse.clocks, clockOffset(ping.at, ping.roundTripMs, Date.now()));
  pulse.clock = keptOffset(pulse.clocks);
  return { type: "pong", at: ping.at };
}

const GONE_REASON = `This page sent nothing for ${PAGE_GONE_AFTER_MS / 1000} s, so its connection was closed.`;

export interface Watched {
  pulse: Pulse;
  send(message: ServerMessage): void;
  drop(reason: string): void;
}

/**
 * Looks at the pages every heartbeat, for as long as the process runs: asks the quiet ones, drops those gone
 * silent. The look is a timer, so after a freeze of the runtime itself it comes late: their silence counts
 * from then.
 */
export function watchPulses(pages: () => Iterable<Watched>): void {
  let since = Date.now();
  let lookedAt = since;
  const timer = setInterval(() => {
    const at = Date.now();
    since = watchingSince(since, lookedAt, at);
    lookedAt = at;
    for (const page of pages()) {
      if (!page.pulse.pinged) continue;
      const check = pageCheck(page.pulse.heardAt, since, at);
      if (check === "ask") page.send({ type: "ping" });
      else if (check === "drop") page.drop(GONE_REASON);
    }
  }, HEARTBEAT_EVERY_MS);
  // Never what keeps the process alive: it ends with the server.
  timer.unref();
}
