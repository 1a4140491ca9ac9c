// A REST request for the HTTP transport, from the action's templates: URL
// placeholders are filled URL-encoded (a parameter cannot change the path or
// add a query), the body as JSON values by the template filler.
import { fillTemplate, fillText } from "./template";
import type { HttpDispatch } from "./types";

export type HttpRequest = { ok: true; method: string; url: string; body?: string } | { ok: false; reason: string };

export function httpRequest(dispatch: HttpDispatch, baseUrl: string, parameters: Record<string, unknown>): HttpRequest {
  const filled = fillText(dispatch.url, parameters, encodeURIComponent);
  if (!filled.ok) return { ok: false, reason: `/url: ${filled.reason}` };
  const path = filled.text;
  let url: string;
  try {
    url = new URL(path, baseUrl).toString();
  } catch {
    return { ok: false, reason: `/url: "${path}" is not a URL` };
  }
  if (!dispatch.body) return { ok: true, method: dispatch.method, url };
  const body = fillTemplate(dispatch.body, parameters);
  if (!body.ok) return { ok: false, reason: `/body${body.path}: ${body.reason}` };
  return { ok: true, method: dispatch.method, url, body: JSON.stringify(body.value) };
}
