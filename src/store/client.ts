import { drizzle } from "drizzle-orm/postgres-js";
import postgres from "postgres";
import * as schema from "./schema";

export type Database = ReturnType<typeof createDatabase>["db"];

export function createDatabase(url: string, options: { max?: number } = {}) {
  const sql = postgres(url, { max: options.max ?? 10, onnotice: () => {} });
  const db = drizzle(sql, { schema });
  return { db, sql, close: () => sql.end({ timeout: 5 }) };
}

/**
 * One connection of its own, never recycled: for what lives as long as a
 * session does (advisory locks). If it drops, the next query opens a new one,
 * and the caller sees the change in `pg_backend_pid()`.
 */
export function createSessionClient(url: string) {
  return postgres(url, { max: 1, max_lifetime: null, idle_timeout: 0, onnotice: () => {} });
}
