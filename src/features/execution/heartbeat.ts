// The page's side of the heartbeat (src/core/socket/heartbeat.ts), for one
// connection from its welcome to its close: a ping every HEARTBEAT_EVERY_MS
// (and at once when the runtime asks), and at each the runtime judged live or
// silent from the oldest ping no message has followed. Any message at all
// brings a silent runtime back to live at once: the connection never closed,
// so nothing it sent meanwhile was lost.
import { HEARTBEAT_EVERY_MS, type RuntimeLink, runtimeLink } from "@/core/socket/heartbeat";
import type { ClientMessage, ServerMessage } from "@/core/socket/messages";

export interface Heartbeat {
  /** Call with every message the runtime sends. */
  heard(message: ServerMessage): void;
  stop(): void;
}

export function startHeartbeat(send: (ping: ClientMessage) => void, onLink: (link: RuntimeLink) => void): Heartbeat {
  // The monotonic clock judges silence (a change of the computer's time must not); the wall clock is what the
  // runtime compares with its own.
  let unansweredSince: number | null = null;
  let roundTripMs: number | undefined;
  let link: RuntimeLink = "live";
  const tell = (now: RuntimeLink) => {
    if (now !== link) onLink((link = now));
  };
  const ping = () => {
    unansweredSince ??= performance.now();
    send({ type: "ping", at: Date.now(), ...(roundTripMs === undefined ? {} : { roundTripMs }) });
  };
  const beat = () => {
    tell(runtimeLink(unansweredSince, performance.now()));
    ping();
  };
  const timer = setInterval(beat, HEARTBEAT_EVERY_MS);
  beat();
  return {
    heard(message) {
      unansweredSince = null;
      if (message.type === "pong") roundTripMs = Math.max(0, Date.now() - message.at);
      tell("live");
      // The runtime asks: answered from here, where a hidden tab's held-back timers do not reach.
      if (message.type === "ping") ping();
    },
    stop: () => clearInterval(timer),
  };
}
