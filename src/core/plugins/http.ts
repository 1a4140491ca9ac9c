// A REST request for the HTTP transport, from the action's templates: URL
// placeholders are filled URL-encoded (a parameter cannot change the path or
// add a query), the body as JSON values by the template filler.
import { fillTemplate } from "./template";
import type { HttpDispatch } from "./types";

export type HttpRequest = { ok: true; method: string; url: string; body?: string } | { ok: false; reason: string };

const PLACEHOLDER = /\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}/g;

export function httpRequest(dispatch: HttpDispatch, baseUrl: string, parameters: Record<string, unknown>): HttpRequest {
  let missing: string | null = null;
  const path = dispatch.url.replace(PLACEHOLDER, (_, name: string) => {
    const value = parameters[name];
    if (value === undefined) missing ??= name;
    return encodeURIComponent(typeof value === "string" ? value : JSON.stringify(value ?? null));
  });
  if (missing) return { ok: false, reason: `/url: no value for parameter "${missing}"` };
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
