// The security headers every response carries. Pages get a Content-Security-
// Policy that lets the app itself work and nothing else: Next.js's inline
// scripts and styles, the trial runtime's WebSocket (on its own port),
// blob: media for the recorder and the player, data: images; no framing by
// any site. API and file routes get a policy that allows nothing at all,
// since nothing they send is meant to run in a browser.

/** On every response, page or route. */
export const COMMON_HEADERS: Record<string, string> = {
  "X-Content-Type-Options": "nosniff",
  "Referrer-Policy": "same-origin",
  "X-Frame-Options": "DENY",
  // The wizard's browser records the session: camera and microphone for this site only.
  "Permissions-Policy": "camera=(self), microphone=(self), geolocation=(), payment=(), usb=(), serial=()",
};

/** For /api routes: JSON, files and media that nothing should run or frame. */
export const API_CSP = "default-src 'none'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'";

/** The scheme, host and port of the trial runtime's URL, as a CSP source. */
function origin(url: string): string {
  const u = new URL(url);
  return `${u.protocol}//${u.host}`;
}

/**
 * For pages; `runtimeUrl` is where browsers reach the trial runtime, and
 * `simulatorUrl` (when `npm start` runs the simulated robot) the robot page's
 * feed. Without either, a page reaches this site only.
 */
export function pageCsp(runtimeUrl?: string, simulatorUrl?: string): string {
  return [
    "default-src 'self'",
    // Next.js writes inline scripts (no nonce: pages are static). Eval: Ajv compiles each robot
    // plugin's parameter schemas into functions in the browser (the designer's forms, the wizard's
    // unscripted actions), and React's development build needs it too.
    "script-src 'self' 'unsafe-inline' 'unsafe-eval'",
    "style-src 'self' 'unsafe-inline'",
    "img-src 'self' blob: data:",
    "media-src 'self' blob:",
    "font-src 'self' data:",
    ["connect-src 'self'", ...[runtimeUrl, simulatorUrl].filter((u): u is string => Boolean(u)).map(origin)].join(" "),
    "worker-src 'self' blob:",
    "object-src 'none'",
    "base-uri 'self'",
    "form-action 'self'",
    "frame-ancestors 'none'",
  ].join("; ");
}
