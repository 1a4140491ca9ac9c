// What the web server refuses from a request's first line and headers alone,
// before Next.js reads a byte of its body or runs any route or page:
// - a method no route of ours can offer (TRACE, CONNECT…): 405, where Next.js
//   itself would fail on it (its Request cannot even hold those methods);
// - anything but reading a page: pages take GET and HEAD only, and no body,
//   which would otherwise be read to its end however large it is;
// - a change (POST, PUT, PATCH, DELETE) that a page of another site could
//   have sent: from another origin, or in a form a browser sends without
//   asking first (a form or text/plain). Our own pages send JSON or a file's
//   own type from this origin; clients without a browser send no Origin.
// One check for every door, so a new route cannot forget it.

/** The methods Next.js's routes can offer; what a route does not offer, Next.js answers 405 itself. */
const METHODS = new Set(["GET", "HEAD", "OPTIONS", "POST", "PUT", "PATCH", "DELETE"]);
const CHANGES = new Set(["POST", "PUT", "PATCH", "DELETE"]);
/** What a browser sends from any page without asking the server first (CORS "simple" requests). */
const SIMPLE_TYPES = new Set(["text/plain", "application/x-www-form-urlencoded", "multipart/form-data"]);

export interface Arrival {
  method: string;
  /** The path, without the query. */
  path: string;
  /** Header names in lower case, as Node.js gives them. */
  headers: Record<string, string | string[] | undefined>;
  /** The app's own origin (BETTER_AUTH_URL): where its pages are served from. */
  origin: string;
}

export interface Refusal {
  status: 403 | 405 | 413 | 415;
  message: string;
  allow?: string;
}

const header = (a: Arrival, name: string) => {
  const value = a.headers[name];
  return Array.isArray(value) ? value.join(", ") : value;
};

/** Next.js's own files and, in development, its tools: not pages of ours. */
const isPage = (path: string) =>
  !path.startsWith("/api/") && !path.startsWith("/_next/") && !path.startsWith("/__nextjs");

const hasBody = (a: Arrival) =>
  header(a, "transfer-encoding") !== undefined || Number(header(a, "content-length") ?? 0) > 0;

function sameOrigin(origin: string, own: string): boolean {
  try {
    return new URL(origin).origin === new URL(own).origin;
  } catch {
    return false;
  }
}

/** Why the request is refused before it reaches Next.js, or null to let it through. */
export function refusal(a: Arrival): Refusal | null {
  const method = a.method.toUpperCase();
  const page = isPage(a.path);
  if (!METHODS.has(method) || (page && method !== "GET" && method !== "HEAD"))
    return {
      status: 405,
      message: `${page ? "A page" : "This address"} does not take ${method.slice(0, 20)} requests${page ? ": it is only read (GET)" : ""}.`,
      ...(page ? { allow: "GET, HEAD" } : {}),
    };
  if (page && hasBody(a)) return { status: 413, message: "A page takes no request body." };
  if (!CHANGES.has(method)) return null;
  const origin = header(a, "origin");
  const site = header(a, "sec-fetch-site");
  if ((origin !== undefined && !sameOrigin(origin, a.origin)) || site === "same-site" || site === "cross-site")
    return { status: 403, message: "A change sent from another site's page is refused: use HRIStudio's own pages." };
  const type = (header(a, "content-type") ?? "").split(";")[0]!.trim().toLowerCase();
  if (SIMPLE_TYPES.has(type) || (type === "" && hasBody(a)))
    return {
      status: 415,
      message: `A change sent as ${type || "no content type"} is refused: a page of another site could send it. Send it with its own type (JSON, or the file's type).`,
    };
  return null;
}
