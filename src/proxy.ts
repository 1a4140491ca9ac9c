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
//
// The session lookup here is the request's one wait on the database: if it
// gets no answer in time, the page is answered here, 503 with the plain
// sentence, and never rendered (rendering would ask the same question and
// wait as long again, then end on Next.js's error page).
import { type NextRequest, NextResponse } from "next/server";
import { readConfig } from "@/store/config";
import { signedInUser } from "@/server/context";
import { databaseUnavailable } from "@/store/client";
import { pageCsp } from "@/server/http/security-headers";
import { browserRuntimeUrl } from "@/server/runtime-url";
import { unavailablePage } from "@/server/http/unavailable-page";

// The simulated robot's address is the launcher's to choose, so it is not a setting of its own.
const signedInCsp = pageCsp(browserRuntimeUrl(readConfig()), process.env.HRI_SIMULATOR_URL);
const anonymousCsp = pageCsp();

export async function proxy(req: NextRequest) {
  // No cookie, no session: nobody is asked (the sign-in page and a participant's form need no lookup).
  let signedIn = false;
  if (req.headers.has("cookie"))
    try {
      signedIn = (await signedInUser(req.headers)) !== null;
    } catch (error) {
      if (databaseUnavailable(error)) return unavailablePage();
      // Any other failure is the page's own to report, when it asks again.
    }
  const response = NextResponse.next();
  response.headers.set("Content-Security-Policy", signedIn ? signedInCsp : anonymousCsp);
  return response;
}

export const config = {
  matcher: ["/((?!api/|_next/static/|_next/image|favicon.ico).*)"],
};
