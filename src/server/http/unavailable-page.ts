// The page a person gets instead of the one they asked for while the database
// cannot be reached: the plain sentence, status 503, and a way to try again.
// It is written out whole, with its own small style in the app's colours,
// because nothing of the app (its layout, its stylesheet, the session behind
// them) can be had without the database.
import { DATABASE_UNAVAILABLE } from "@/store/client";
import { COMMON_HEADERS, pageCsp } from "./security-headers";

const HTML = `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>HRIStudio</title>
<style>
body { margin: 0; min-height: 100vh; display: flex; align-items: center; justify-content: center;
  font-family: ui-sans-serif, system-ui, sans-serif; background: #f8fafc; color: #0f172a; }
main { max-width: 24rem; margin: 1.5rem; padding: 2rem; background: #fff; border: 1px solid #e2e8f0; border-radius: 0.75rem; }
h1 { margin: 0 0 1rem; font-size: 1.5rem; font-weight: 600; color: #1d4793; }
a { color: #2458b8; }
</style>
</head>
<body>
<main>
<h1>HRIStudio</h1>
<p>${DATABASE_UNAVAILABLE}</p>
<p><a href="">Try again</a></p>
</main>
</body>
</html>
`;

/** Status 503, never cached, with the policy a stranger's page gets (nothing of the deployment is named). */
export function unavailablePage(): Response {
  return new Response(HTML, {
    status: 503,
    headers: {
      ...COMMON_HEADERS,
      "Content-Security-Policy": pageCsp(),
      "Content-Type": "text/html; charset=utf-8",
      "Cache-Control": "no-store",
      "Retry-After": "5",
    },
  });
}
