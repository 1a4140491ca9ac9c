// A column named with its table. Drizzle leaves the table out in a
// single-table select, so inside a correlated subquery "id" would read the
// subquery's own table: counts silently came out as zero.
import { getTableName, sql, type Column } from "drizzle-orm";

export const qualified = (column: Column) =>
  sql`${sql.identifier(getTableName(column.table))}.${sql.identifier(column.name)}`;
