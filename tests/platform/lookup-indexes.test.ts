// Every lookup a page makes by a foreign key has an index to use: without one,
// the Trials tab's counts and a study's deletion scan whole tables, and their
// cost grows with every study on the server. Read from the migrated schema.
import { sql } from "drizzle-orm";
import { afterAll, expect, it } from "vitest";
import { freshDatabase } from "../support/db";

const { db, close } = await freshDatabase();
afterAll(close);

// Who made or did something (created_by, published_by, actor_id, author_id…):
// read only when an account is deleted, which an administrator does rarely,
// so these columns carry no index of their own.
const authorship = (key: string, references: string) =>
  references === "user" && /\.(\w+_by|actor_id|author_id)$/.test(key);

it("has an index leading with every foreign key column", async () => {
  const rows = await db.execute<{ key: string; references: string }>(sql`
    select c.conrelid::regclass::text || '.' || a.attname as key, c.confrelid::regclass::text as references
    from pg_constraint c
    join pg_attribute a on a.attrelid = c.conrelid and a.attnum = c.conkey[1]
    where c.contype = 'f' and c.connamespace = 'public'::regnamespace
      and not exists (
        select 1 from pg_index i where i.indrelid = c.conrelid and i.indkey[0] = c.conkey[1]
      )
    order by 1`);
  const unindexed = rows
    .map((r) => ({ key: r.key.replaceAll('"', ""), references: r.references.replaceAll('"', "") }))
    .filter((r) => !authorship(r.key, r.references))
    .map((r) => r.key);
  expect(unindexed).toEqual([]);
});
