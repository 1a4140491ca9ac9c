// An unexpected error reaches the person as a plain sentence and a reference;
// what went wrong (SQL, parameters, stack) stays in the server's log under it.
import { randomBytes } from "node:crypto";

/** Logs the error under a new reference and returns the reference. */
export function logWithReference(error: unknown, where: string): string {
  const reference = randomBytes(4).toString("hex").toUpperCase();
  const detail = error instanceof Error ? (error.stack ?? error.message) : String(error);
  console.error(`[hristudio] error ${reference} in ${where}: ${detail}`);
  return reference;
}

export function unexpectedMessage(reference: string): string {
  return `Something went wrong on the server, and this was not done. Please try again; if it happens again, tell your administrator the reference ${reference}.`;
}
