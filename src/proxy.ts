// Every page's Content-Security-Policy, set when the page is served: it names
// the trial runtime's address, which is configured when the app starts, not
// when it is built. The other security headers (and the /api routes' policy)
// come from next.config.ts. /api is left out here on purpose: with a proxy in
// front of a route, Next.js buffers the request body (up to 10 MB) before the
// route can apply its own limit while reading.
import { NextResponse } from "next/server";
import { readConfig } from "@/store/config";
import { pageCsp } from "@/server/http/security-headers";
import { browserRuntimeUrl } from "@/server/runtime-url";

// The simulated robot's address is the launcher's to choose, so it is not a setting of its own.
const csp = pageCsp(browserRuntimeUrl(readConfig()), process.env.HRI_SIMULATOR_URL);

export function proxy() {
  const response = NextResponse.next();
  response.headers.set("Content-Security-Policy", csp);
  return response;
}

export const config = {
  matcher: ["/((?!api/|_next/static/|_next/image|favicon.ico).*)"],
};
