// A body read with a limit, counted while it arrives: one that declares too
// large a length is refused before a byte is read, and one that turns out
// too large (chunked, endless, or lying about its length) is cut off as soon
// as the count passes the limit, so no more than the limit is ever held.
// Requests the web server takes and files a plugin sync fetches share it.
import { KB, MB } from "./limits";

/** "1 MB", "64 KB", "10 bytes". */
export const sizeText = (bytes: number) =>
  bytes >= MB ? `${+(bytes / MB).toFixed(1)} MB` : bytes >= KB ? `${+(bytes / KB).toFixed(1)} KB` : `${bytes} bytes`;

export type BoundedBody =
  | { ok: true; bytes: Uint8Array<ArrayBuffer> }
  /** Over the limit; `declared` is the length it said it had, when that was already too large. */
  | { ok: false; declared?: number };

/** The bytes of a request's or a response's body, or why not: more than `limit`. */
export async function readWithin(
  message: { headers: Headers; body: ReadableStream<Uint8Array> | null },
  limit: number,
): Promise<BoundedBody> {
  const declared = message.headers.get("content-length");
  if (declared !== null && Number(declared) > limit) {
    await message.body?.cancel().catch(() => {});
    return { ok: false, declared: Number(declared) };
  }
  if (!message.body) return { ok: true, bytes: new Uint8Array(0) };
  const reader = message.body.getReader();
  const parts: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.byteLength;
    if (total > limit) {
      // Stop pulling: the rest is never read.
      await reader.cancel().catch(() => {});
      return { ok: false };
    }
    parts.push(value);
  }
  const bytes = new Uint8Array(total);
  let at = 0;
  for (const part of parts) {
    bytes.set(part, at);
    at += part.byteLength;
  }
  return { ok: true, bytes };
}
