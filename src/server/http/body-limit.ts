// Request bodies are read with a limit, counted while they arrive
// (readWithin): the server never holds more than the limit of one.

import { readWithin, sizeText } from "@/core/network/bounded-body";

/** 413 with a sentence naming the limit, e.g. "A part of a recording may be at most 16 MB; this one is 20 MB." */
export function tooLarge(what: string, limit: number, declared?: number): Response {
  const actual = declared === undefined ? "this one is larger" : `this one is ${sizeText(declared)}`;
  return new Response(`${what} may be at most ${sizeText(limit)}; ${actual}.`, {
    status: 413,
    headers: { "content-type": "text/plain; charset=utf-8", connection: "close" },
  });
}

/**
 * The body's bytes, or a 413 Response when it is larger than `limit`.
 * `what` names the body for the message ("A part of a recording").
 */
export async function readBody(req: Request, limit: number, what: string): Promise<Uint8Array<ArrayBuffer> | Response> {
  const read = await readWithin(req, limit);
  return read.ok ? read.bytes : tooLarge(what, limit, read.declared);
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
