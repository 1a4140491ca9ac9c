import { describe, expect, it } from "vitest";
import { type Arrival, refusal } from "./request-gate";

const OWN = "http://localhost:3000";
const arrive = (method: string, path: string, headers: Arrival["headers"] = {}): Arrival => ({
  method,
  path,
  headers,
  origin: OWN,
});
const json = { "content-type": "application/json", "content-length": "2" };

describe("what the web server refuses before Next.js sees it", () => {
  it.each<[string, Arrival, number | null]>([
    ["reading a page", arrive("GET", "/studies"), null],
    ["a page's head", arrive("HEAD", "/robot"), null],
    ["TRACE on a page", arrive("TRACE", "/sign-in"), 405],
    ["TRACE on a route", arrive("TRACE", "/api/trpc/studies.mine"), 405],
    ["CONNECT anywhere", arrive("CONNECT", "/api/auth/ok"), 405],
    ["a POST to a page", arrive("POST", "/sign-in", { ...json, origin: OWN }), 405],
    ["a page read with a body", arrive("GET", "/", { "content-length": String(2 ** 30) }), 413],
    ["a page read with a chunked body", arrive("GET", "/robot", { "transfer-encoding": "chunked" }), 413],
    ["a page read with an empty body", arrive("GET", "/", { "content-length": "0" }), null],
    ["Next.js's own files", arrive("GET", "/_next/static/chunks/app.js"), null],
    ["the API read with a body is the route's to judge", arrive("GET", "/api/trpc/x", { "content-length": "9" }), null],
    ["a change from our own page", arrive("POST", "/api/trpc/studies.create", { ...json, origin: OWN }), null],
    ["a change from a client without a browser", arrive("PUT", "/api/recordings/r/chunks/0", json), null],
    [
      "a sound from our own page",
      arrive("POST", "/api/studies/s/audio", { "content-type": "audio/wav", origin: OWN }),
      null,
    ],
    [
      "a change from another origin",
      arrive("POST", "/api/studies/s/audio", { ...json, origin: "http://lab.example:3000" }),
      403,
    ],
    [
      "a change from another port",
      arrive("POST", "/api/auth/sign-out", { ...json, origin: "http://localhost:3001" }),
      403,
    ],
    ["a change from a sandboxed page", arrive("POST", "/api/trpc/x", { ...json, origin: "null" }), 403],
    [
      "a change a same-site page sent",
      arrive("DELETE", "/api/trpc/x", { ...json, "sec-fetch-site": "same-site" }),
      403,
    ],
    [
      "a change our own page sent",
      arrive("POST", "/api/trpc/x", { ...json, "sec-fetch-site": "same-origin", origin: OWN }),
      null,
    ],
    [
      "text/plain",
      arrive("POST", "/api/studies/s/audio", { "content-type": "text/plain;charset=UTF-8", origin: OWN }),
      415,
    ],
    ["a form", arrive("POST", "/api/studies/s/audio", { "content-type": "application/x-www-form-urlencoded" }), 415],
    [
      "a file form",
      arrive("PUT", "/api/recordings/r/chunks/0", { "content-type": "multipart/form-data; boundary=x" }),
      415,
    ],
    ["a body of no type", arrive("POST", "/api/studies/s/audio", { "content-length": "40" }), 415],
    ["a change with no body and no type", arrive("POST", "/api/auth/sign-out", { origin: OWN }), null],
    [
      "reading across sites (a download link)",
      arrive("GET", "/api/trials/t/export", { "sec-fetch-site": "cross-site" }),
      null,
    ],
  ])("%s", (_, arrival, status) => {
    expect(refusal(arrival)?.status ?? null).toBe(status);
  });

  it("names what pages take", () => {
    expect(refusal(arrive("TRACE", "/robot"))).toEqual({
      status: 405,
      message: "A page does not take TRACE requests: it is only read (GET).",
      allow: "GET, HEAD",
    });
  });
});
