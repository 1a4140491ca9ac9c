// What the database holds, read from PostgreSQL's catalogue rather than our
// Drizzle schema, so a backup takes every table there is, declared or not.
import type postgres from "postgres";
import type { Reference } from "@/core/backup/table-order";
import { migrationLevel, type JournalEntry, type MigrationLevel } from "@/core/backup/migration-level";

type Sql = postgres.Sql | postgres.TransactionSql;

export const quoteIdent = (name: string) => `"${name.replaceAll('"', '""')}"`;

/**
 * The same on both ends, so COPY's text reads back exactly: timestamps in
 * UTC with microseconds, floats to the last bit, bytea as hex.
 */
export async function fixTextFormats(tx: postgres.TransactionSql) {
  await tx.unsafe(
    "SET LOCAL TIME ZONE 'UTC'; SET LOCAL datestyle = 'ISO, YMD'; SET LOCAL intervalstyle = 'postgres'; SET LOCAL extra_float_digits = 3; SET LOCAL bytea_output = 'hex'",
  );
}

/** Every table of the public schema with its stored columns, in column order. */
export async function tablesOf(sql: Sql): Promise<Array<{ name: string; columns: string[] }>> {
  const rows = await sql<Array<{ table: string; columns: string[] }>>`
    SELECT c.relname AS table, array_agg(a.attname::text ORDER BY a.attnum) AS columns
    FROM pg_class c
    JOIN pg_namespace n ON n.oid = c.relnamespace
    JOIN pg_attribute a ON a.attrelid = c.oid AND a.attnum > 0 AND NOT a.attisdropped AND a.attgenerated = ''
    WHERE n.nspname = 'public' AND c.relkind IN ('r', 'p')
    GROUP BY c.relname ORDER BY c.relname`;
  return rows.map((r) => ({ name: r.table, columns: r.columns }));
}

/** Foreign keys between tables of the public schema. */
export async function referencesOf(sql: Sql): Promise<Reference[]> {
  return sql<Reference[]>`
    SELECT c.relname AS from, p.relname AS to
    FROM pg_constraint k
    JOIN pg_class c ON c.oid = k.conrelid
    JOIN pg_class p ON p.oid = k.confrelid
    JOIN pg_namespace n ON n.oid = c.relnamespace
    WHERE k.contype = 'f' AND n.nspname = 'public'`;
}

export async function sequencesOf(sql: Sql): Promise<string[]> {
  const rows = await sql<Array<{ name: string }>>`
    SELECT c.relname AS name FROM pg_class c JOIN pg_namespace n ON n.oid = c.relnamespace
    WHERE n.nspname = 'public' AND c.relkind = 'S' ORDER BY c.relname`;
  return rows.map((r) => r.name);
}

/** The tables that hold at least one row. */
export async function tablesWithRows(sql: Sql): Promise<string[]> {
  const found: string[] = [];
  for (const { name } of await tablesOf(sql)) {
    const [row] = await sql.unsafe<Array<{ any: boolean }>>(`SELECT EXISTS (SELECT 1 FROM ${quoteIdent(name)}) AS any`);
    if (row!.any) found.push(name);
  }
  return found;
}

/** How far the committed migrations have been applied (Drizzle records each in drizzle.__drizzle_migrations). */
export async function appliedLevel(sql: Sql, journal: JournalEntry[]): Promise<MigrationLevel> {
  const [{ exists }] =
    (await sql`SELECT to_regclass('drizzle.__drizzle_migrations') IS NOT NULL AS exists`) as unknown as [
      { exists: boolean },
    ];
  if (!exists) return migrationLevel(journal, []);
  const rows = await sql<Array<{ when: string }>>`SELECT created_at::text AS when FROM drizzle.__drizzle_migrations`;
  return migrationLevel(
    journal,
    rows.map((r) => Number(r.when)),
  );
}
