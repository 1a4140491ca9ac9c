// What the trial socket takes from a browser, declared once beside its
// messages: a connection that has not said hello is nobody yet, so it gets a
// frame the size of a hello, a few seconds to send it, and only a few like it
// from one address at a time. After hello, each kind of message has its own
// size; the largest of them is the most the server reads of any frame at all.
import type { ClientMessage } from "./messages";

const KB = 1024;

/** A hello is a few hundred bytes (its token may be up to 4,000 characters). */
export const HELLO_FRAME_BYTES = 8 * KB;

/** A browser says hello as soon as it is connected; one that has not by then is closed. */
export const HELLO_DEADLINE_MS = 5000;

/**
 * Connections from one address that have not said hello yet, at once. A lab's browsers share one address
 * behind its router and all reconnect at once after a restart (and the benchmarks open hundreds of sockets
 * from one): enough for them, while one address still cannot hold thousands of idle sockets.
 */
export const UNGREETED_PER_ADDRESS = 50;

/** The most each kind of message may take, in bytes, with room for JSON's escapes of its longest texts. */
export const MESSAGE_BYTES: Record<ClientMessage["type"], number> = {
  hello: HELLO_FRAME_BYTES,
  // A note of 5,000 characters, or an unscripted action's parameters.
  command: 64 * KB,
  annotate: 32 * KB,
  code: 16 * KB,
  ping: 1 * KB,
  replay: 1 * KB,
  replay_stop: 1 * KB,
  camera: 1 * KB,
  // A WebRTC session description of up to 100,000 characters.
  signal: 256 * KB,
};

/** The server reads no frame larger than this (Bun's maxPayloadLength): larger ones close the connection. */
export const LARGEST_FRAME_BYTES = Math.max(...Object.values(MESSAGE_BYTES));

const size = (bytes: number) =>
  bytes < KB
    ? `${bytes} bytes`
    : bytes < KB * KB
      ? `${Math.ceil(bytes / KB)} KB`
      : `${(bytes / (KB * KB)).toFixed(1)} MB`;

/** Why a frame that came before hello closes its connection, or null. */
export function beforeHelloRefusal(bytes: number): string | null {
  if (bytes <= HELLO_FRAME_BYTES) return null;
  return `The first message must be a hello of a few hundred bytes; this one had ${size(bytes)}, so the connection was closed.`;
}

/** Why a message of this kind is refused for its size, or null. */
export function sizeRefusal(type: ClientMessage["type"], bytes: number): string | null {
  const most = MESSAGE_BYTES[type];
  if (bytes <= most) return null;
  return `That ${type} message is too large (${size(bytes)}; at most ${size(most)}): nothing was done.`;
}
