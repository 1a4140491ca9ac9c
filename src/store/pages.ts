// A table too large to hold, read a page at a time in a total order, each page
// after the last row of the one before (keyed paging: an index finds where the
// page starts, no offset is skipped over, however deep the page).
import { type AnyColumn, type SQL, sql } from "drizzle-orm";

/** A row's place in the order a table is read in: the values of its ordering columns. */
export type Key = unknown[];

/**
 * The rows `read` gives, page by page: `read` gets the key (see keyOf) of the
 * last row of the page before (undefined for the first) and returns at most
 * `limit` rows after it. The next page is read while the reader works on this
 * one, so the database and the reader overlap, and at most two pages are held.
 */
export async function* keyedPages<T>(
  read: (after: Key | undefined) => Promise<T[]>,
  keyOf: (row: T) => Key,
  limit: number,
): AsyncGenerator<T[]> {
  const ahead = (after: Key | undefined) => {
    const rows = read(after);
    // A reader that stops early leaves the page read ahead unread: its failure is nobody's to hear.
    rows.catch(() => {});
    return rows;
  };
  for (let next: Promise<T[]> | null = ahead(undefined); next; ) {
    const rows: T[] = await next;
    next = rows.length === limit ? ahead(keyOf(rows.at(-1)!)) : null;
    if (rows.length) yield rows;
  }
}

/**
 * The rows after the key `values` in the order of `columns` (none given: every
 * row), as one row comparison, which an index on those columns answers.
 */
export function after(columns: AnyColumn[], values: Key | undefined): SQL | undefined {
  if (!values) return undefined;
  return sql`(${sql.join(columns, sql`, `)}) > (${sql.join(
    values.map((v) => sql`${v}`),
    sql`, `,
  )})`;
}
