// An unexpected error (a bug, a database or storage failure) reaches the
// client as one plain sentence with a reference; the details (message, SQL
// and its parameters, stack) go only to the server's log, under the same
// reference, so an administrator can find them from what the user reports.
import { inspect } from "node:util";

/** Logs the error with a new reference and returns the reference. */
export function logUnexpected(error: unknown, where: string): string {
  const ref = crypto.randomUUID().slice(0, 8);
  console.error(`[hristudio] error ${ref}: ${where}: ${inspect(error, { depth: 4 })}`);
  return ref;
}

/** What the client is told instead of the error itself. */
export const unexpectedMessage = (ref: string) =>
  `Something went wrong on the server. If it happens again, tell your administrator the reference ${ref}.`;

/** A route's answer to an unexpected error: logged, and 500 with the plain message. */
export function unexpectedResponse(error: unknown, req: Request): Response {
  const ref = logUnexpected(error, `${req.method} ${new URL(req.url).pathname}`);
  return new Response(unexpectedMessage(ref), {
    status: 500,
    headers: { "content-type": "text/plain; charset=utf-8" },
  });
}
