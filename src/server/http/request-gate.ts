// The web server's side of the request gate (src/core/network/request-gate.ts):
// a refused request is answered at once and its connection closed, so no byte
// of its body is read; the answer carries the headers every response has.
import type { IncomingMessage, ServerResponse } from "node:http";
import { refusal } from "../../core/network/request-gate";
import { API_CSP, COMMON_HEADERS } from "./security-headers";

/** Answers a refused request and says true; says false for one Next.js may have. */
export function refused(req: IncomingMessage, res: ServerResponse, origin: string): boolean {
  const path = (req.url ?? "/").split("?")[0]!;
  const why = refusal({ method: req.method ?? "GET", path, headers: req.headers, origin });
  if (!why) return false;
  res.writeHead(why.status, {
    ...COMMON_HEADERS,
    "content-security-policy": API_CSP,
    "content-type": "text/plain; charset=utf-8",
    connection: "close",
    ...(why.allow ? { allow: why.allow } : {}),
  });
  res.end(why.message);
  return true;
}
