import { drizzle } from "drizzle-orm/postgres-js";
import postgres from "postgres";
import * as schema from "./schema";

export type Database = ReturnType<typeof createDatabase>["db"];

/**
 * How every client of ours reconnects after the database went away. The
 * driver's defaults wait up to 20 s between attempts (its backoff grows with
 * every refused connection, 3^n / 100 s) and 30 s for a connection to open:
 * after a restart of PostgreSQL, queries waited for a connection that had
 * long been possible, and one caught mid-connect by the restart waited for
 * good. A wizard's command must be answered in seconds, so attempts are
 * retried within a second and a connection that does not open in 5 s fails
 * the query, plainly.
 */
const RECONNECT = {
  backoff: (attempt: number) => Math.min(0.05 * 2 ** attempt, 1),
  connect_timeout: 5,
} as const;

export function createDatabase(url: string, options: { max?: number } = {}) {
  const sql = postgres(url, { max: options.max ?? 10, onnotice: () => {}, ...RECONNECT });
  const db = drizzle(sql, { schema });
  return { db, sql, close: () => sql.end({ timeout: 5 }) };
}

/**
 * One connection of its own, never recycled: for what lives as long as a
 * session does (advisory locks). If it drops, the next query opens a new one,
 * and the caller sees the change in `pg_backend_pid()`.
 */
export function createSessionClient(
  url: string,
  /** Told as soon as its connection closes (ended by the server, a restart, a network loss): its session went with it. */
  closed: () => void = () => {},
) {
  return postgres(url, {
    max: 1,
    max_lifetime: null,
    idle_timeout: 0,
    onnotice: () => {},
    onclose: () => closed(),
    ...RECONNECT,
  });
}

/**
 * Errors raised before a statement reached the server (nothing listened, the
 * server was still starting, no connection opened in time): nothing of it can
 * have been stored. Any other failure may have committed.
 */
export function neverReachedDatabase(error: unknown): boolean {
  const code = (error as { code?: string } | null)?.code ?? "";
  return ["ECONNREFUSED", "CONNECT_TIMEOUT", "57P03"].includes(code);
}

/**
 * An error the server answered with (the statement ran and failed): its
 * transaction rolled back, so nothing of it was stored. A failure of the
 * connection instead leaves the outcome unknown.
 */
export function refusedByDatabase(error: unknown): boolean {
  return typeof (error as { severity?: unknown } | null)?.severity === "string";
}

/** The code a caller gives its own error for a connection that went silent (its query timed out). */
export const NO_ANSWER = "NO_ANSWER";

/** Long enough for a loaded database, short enough that a silent one (frozen, unreachable) is not waited on for long. */
export const ANSWER_MS = 5000;

/**
 * The query, or a NO_ANSWER error once the database has been silent for
 * `ms`. A frozen server keeps its connections open and answers nothing, so
 * neither the driver nor the server's own timeouts ever end such a query.
 */
export function answered<T>(query: Promise<T>, silent: string, ms = ANSWER_MS): Promise<T> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const silence = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(Object.assign(new Error(silent), { code: NO_ANSWER })), ms);
  });
  return Promise.race([query, silence]).finally(() => clearTimeout(timer));
}

/** What a person is told while the database cannot be reached. */
export const DATABASE_UNAVAILABLE = "The database is unavailable; try again in a moment.";

/**
 * The database could not be reached, or did not answer: nobody's fault, and
 * worth trying again shortly. Libraries wrap the driver's error (the query
 * builder, the sign-in library), so its causes are looked through too.
 */
export function databaseUnavailable(error: unknown): boolean {
  for (let e = error, depth = 0; e && depth < 5; e = (e as { cause?: unknown }).cause, depth++)
    if (neverReachedDatabase(e) || connectionLost(e)) return true;
  return false;
}

/** The connection itself went, or went silent (`NO_ANSWER`): not that the statement was wrong. */
export function connectionLost(error: unknown): boolean {
  const code = (error as { code?: string } | null)?.code ?? "";
  return [
    NO_ANSWER,
    "CONNECTION_CLOSED",
    "CONNECTION_ENDED",
    "CONNECTION_DESTROYED",
    "57P01",
    "ECONNRESET",
    "ECONNREFUSED",
  ].includes(code);
}
