// A welcome in parts. A trial's whole log (about 10 MB for 100,000 events) in
// one frame holds the runtime's event loop while it is written, and every
// other trial's commands wait behind it. So the log goes ahead of the welcome
// as "welcome.part" messages of at most WELCOME_PART_BYTES, numbered from 0,
// sent one turn of the event loop at a time; the "welcome" itself carries the
// last events and how many parts came before it, and the client joins them.
import type { ServerMessage, WireEvent } from "./messages";

export const WELCOME_PART_BYTES = 256 * 1024;

/** A part's own text around its events: `{"type":"welcome.part","part":N,"events":[…]}`. */
const ENVELOPE_BYTES = 64;

/**
 * Where each part ends (exclusive), given each event's size in bytes as sent: a part holds events while their
 * texts, with the commas between them and its envelope, fit in `limit`; an event larger than that goes alone.
 * The last part is the welcome's own.
 */
export function partEnds(sizes: number[], limit = WELCOME_PART_BYTES): number[] {
  const ends: number[] = [];
  let start = 0;
  let bytes = ENVELOPE_BYTES;
  for (const [i, size] of sizes.entries()) {
    const added = (i > start ? 1 : 0) + size;
    if (i > start && bytes + added > limit) {
      ends.push(i);
      start = i;
      bytes = ENVELOPE_BYTES + size;
    } else bytes += added;
  }
  ends.push(sizes.length);
  return ends;
}

type Welcome = Extract<ServerMessage, { type: "welcome" }>;
export type Joined = { ok: true; message: ServerMessage | null } | { ok: false; reason: string };

/**
 * The client's side, one per connection: each message as it comes, a part held (null) until the welcome, which
 * comes back with every part's events before its own. Parts missing or out of order are said, never folded.
 */
export function welcomeJoiner() {
  let held: WireEvent[] = [];
  let parts = 0;
  return (message: ServerMessage): Joined => {
    if (message.type === "welcome.part") {
      if (message.part !== parts)
        return { ok: false, reason: `Part ${message.part} of the trial's welcome came where part ${parts} was due.` };
      parts++;
      for (const event of message.events) held.push(event);
      return { ok: true, message: null };
    }
    if (message.type !== "welcome") return { ok: true, message };
    const came = parts;
    const events = held;
    held = [];
    parts = 0;
    if (message.parts !== came)
      return { ok: false, reason: `The trial's welcome came after ${came} of its ${message.parts} parts.` };
    for (const event of message.events) events.push(event);
    return { ok: true, message: { ...message, events } satisfies Welcome };
  };
}
