// Talks to a running app the way a browser does: a session cookie and tRPC over HTTP.
import { createTRPCClient, httpLink } from "@trpc/client";
import type { AppRouter } from "../../src/server/api/root";

export async function signIn(baseUrl: string, email: string, password: string): Promise<string> {
  const res = await fetch(`${baseUrl}/api/auth/sign-in/email`, {
    method: "POST",
    headers: { "content-type": "application/json", origin: baseUrl },
    body: JSON.stringify({ email, password }),
  });
  if (!res.ok) throw new Error(`Sign-in as ${email} failed: ${res.status} ${await res.text()}`);
  return res.headers
    .getSetCookie()
    .map((c) => c.split(";")[0])
    .join("; ");
}

/** With `heard`, every response body the server sends this caller is kept there. */
export function apiClient(baseUrl: string, cookie?: string, heard?: string[]) {
  const fetchAndKeep = async (url: Parameters<typeof fetch>[0], init?: Parameters<typeof fetch>[1]) => {
    const res = await fetch(url, init).catch((error: unknown) => {
      // A kept-alive connection the server closed as the request went out (its idle timeout and the client's
      // meet on a loaded machine): sent again once on a new one, as a browser does. Found by CI.
      if ((error as { cause?: { code?: string } }).cause?.code !== "UND_ERR_SOCKET") throw error;
      return fetch(url, init);
    });
    heard?.push(await res.clone().text());
    return res;
  };
  return createTRPCClient<AppRouter>({
    links: [httpLink({ url: `${baseUrl}/api/trpc`, headers: () => (cookie ? { cookie } : {}), fetch: fetchAndKeep })],
  });
}
