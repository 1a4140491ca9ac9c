// An unexpected error (a bug, a database or storage failure) reaches the
// client as one plain sentence with a reference; the details (message, SQL
// and its parameters, stack) go only to the server's log, under the same
// reference, so an administrator can find them from what the user reports.
// A database that cannot be reached is no bug: that is said as it is (503).
import { inspect } from "node:util";
import { DATABASE_UNAVAILABLE, databaseUnavailable } from "./client";

/** Logs the error with a new reference and returns the reference. */
export function logUnexpected(error: unknown, where: string): string {
  const ref = crypto.randomUUID().slice(0, 8);
  console.error(`[hristudio] error ${ref}: ${where}: ${inspect(error, { depth: 4 })}`);
  return ref;
}

/** What the client is told instead of the error itself. */
export const unexpectedMessage = (ref: string) =>
  `Something went wrong on the server. If it happens again, tell your administrator the reference ${ref}.`;

/** What the client is told of an unexpected error, and with which status; the details go to the log. */
export function failure(error: unknown, where: string): { status: 500 | 503; message: string } {
  if (databaseUnavailable(error)) {
    console.error(`[hristudio] ${where}: the database could not be reached.`);
    return { status: 503, message: DATABASE_UNAVAILABLE };
  }
  return { status: 500, message: unexpectedMessage(logUnexpected(error, where)) };
}

/** A route's answer to an unexpected error: the plain message of `failure`, as text. */
export function unexpectedResponse(error: unknown, req: Request): Response {
  const { status, message } = failure(error, `${req.method} ${new URL(req.url).pathname}`);
  return new Response(message, { status, headers: { "content-type": "text/plain; charset=utf-8" } });
}
