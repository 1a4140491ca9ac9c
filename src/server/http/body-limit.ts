// Request bodies are read with a limit, counted while they arrive: a body
// that declares too large a length is refused before a byte is read, and one
// that turns out too large (chunked, or lying about its length) is cut off
// as soon as the count passes the limit, so the server never holds more than
// the limit of it.

import { KB, MB } from "@/core/network/limits";

const size = (bytes: number) =>
  bytes >= MB ? `${+(bytes / MB).toFixed(1)} MB` : bytes >= KB ? `${+(bytes / KB).toFixed(1)} KB` : `${bytes} bytes`;

/** 413 with a sentence naming the limit, e.g. "A part of a recording may be at most 16 MB; this one is 20 MB." */
export function tooLarge(what: string, limit: number, declared?: number): Response {
  const actual = declared === undefined ? "this one is larger" : `this one is ${size(declared)}`;
  return new Response(`${what} may be at most ${size(limit)}; ${actual}.`, {
    status: 413,
    headers: { "content-type": "text/plain; charset=utf-8", connection: "close" },
  });
}

/**
 * The body's bytes, or a 413 Response when it is larger than `limit`.
 * `what` names the body for the message ("A part of a recording").
 */
export async function readBody(req: Request, limit: number, what: string): Promise<Uint8Array<ArrayBuffer> | Response> {
  const declared = req.headers.get("content-length");
  if (declared !== null && Number(declared) > limit) {
    await req.body?.cancel().catch(() => {});
    return tooLarge(what, limit, Number(declared));
  }
  if (!req.body) return new Uint8Array(0);
  const reader = req.body.getReader();
  const parts: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.byteLength;
    if (total > limit) {
      // Stop pulling: the rest is never read.
      await reader.cancel().catch(() => {});
      return tooLarge(what, limit);
    }
    parts.push(value);
  }
  const body = new Uint8Array(total);
  let at = 0;
  for (const part of parts) {
    body.set(part, at);
    at += part.byteLength;
  }
  return body;
}

/** The request again, its body read within the limit (for handlers that read the body themselves), or a 413. */
export async function withinLimit(req: Request, limit: number, what: string): Promise<Request | Response> {
  if (req.method === "GET" || req.method === "HEAD") return req;
  const body = await readBody(req, limit, what);
  if (body instanceof Response) return body;
  // The copy has a known length: it is no longer sent in chunks.
  const headers = new Headers(req.headers);
  headers.delete("transfer-encoding");
  headers.set("content-length", String(body.byteLength));
  return new Request(req.url, { method: req.method, headers, body, signal: req.signal });
}
