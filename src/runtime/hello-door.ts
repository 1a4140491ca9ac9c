// The trial socket's door: a connection that has not said hello is nobody
// yet, so it may wait only so long (HELLO_DEADLINE_MS), and only so many may
// wait from one address at once (UNGREETED_PER_ADDRESS). What it may send
// meanwhile is limited where its frames are read (server.ts, limits.ts).
import { HELLO_DEADLINE_MS, UNGREETED_PER_ADDRESS } from "@/core/socket/limits";

/** Close codes (RFC 6455): the browser reconnects after them, as after any other drop. */
const POLICY = 1008;
const TRY_LATER = 1013;

export function helloDoor() {
  /** Connections waiting to say hello, per address (only addresses with some). */
  const waiting = new Map<string, number>();
  return {
    /**
     * A new connection from `address`: refused at once (`shut`) when too many from there are waiting, else
     * shut when its deadline passes. Returns what to call once it said hello or went away; null if refused.
     */
    enter(address: string, shut: (code: number, reason: string) => void): (() => void) | null {
      const already = waiting.get(address) ?? 0;
      if (already >= UNGREETED_PER_ADDRESS) {
        shut(TRY_LATER, "Too many connections from your address have not said hello yet: try again in a few seconds.");
        return null;
      }
      waiting.set(address, already + 1);
      const deadline = setTimeout(
        () => shut(POLICY, `No hello came within ${HELLO_DEADLINE_MS / 1000} s, so the connection was closed.`),
        HELLO_DEADLINE_MS,
      );
      let left = false;
      return () => {
        if (left) return;
        left = true;
        clearTimeout(deadline);
        const still = (waiting.get(address) ?? 1) - 1;
        if (still > 0) waiting.set(address, still);
        else waiting.delete(address);
      };
    },
  };
}
