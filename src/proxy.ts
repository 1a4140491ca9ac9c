// Every page's Content-Security-Policy, set when the page is served: it names
// the trial runtime's address, which is configured when the app starts, not
// when it is built. The other security headers (and the /api routes' policy)
// come from next.config.ts. /api is left out here on purpose: with a proxy in
// front of a route, Next.js buffers the request body (up to 10 MB) before the
// route can apply its own limit while reading.
//
// The runtime's and the simulated robot's addresses are the deployment's own:
// someone not signed in learns neither (their pages reach nothing but this
// site), not even from a page that only redirects them to the sign-in.
import { type NextRequest, NextResponse } from "next/server";
import { readConfig } from "@/store/config";
import { signedInUser } from "@/server/context";
import { pageCsp } from "@/server/http/security-headers";
import { browserRuntimeUrl } from "@/server/runtime-url";

// The simulated robot's address is the launcher's to choose, so it is not a setting of its own.
const signedInCsp = pageCsp(browserRuntimeUrl(readConfig()), process.env.HRI_SIMULATOR_URL);
const anonymousCsp = pageCsp();

export async function proxy(req: NextRequest) {
  // No cookie, no session: nobody is asked. A database that does not answer leaves the page its own failure.
  const signedIn = req.headers.has("cookie") && (await signedInUser(req.headers).catch(() => null)) !== null;
  const response = NextResponse.next();
  response.headers.set("Content-Security-Policy", signedIn ? signedInCsp : anonymousCsp);
  return response;
}

export const config = {
  matcher: ["/((?!api/|_next/static/|_next/image|favicon.ico).*)"],
};
