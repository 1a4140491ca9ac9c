import { cpSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import postgres from "postgres";
import { describe, expect, it } from "vitest";
import { freshDatabaseUrl } from "../../tests/support/db";
import { scratchFolder } from "../../tests/support/scratch";
import { migrateDatabase, MIGRATIONS_DIR } from "./migrate";

interface Journal {
  entries: Array<{ idx: number; tag: string }>;
}
const journal: Journal = JSON.parse(readFileSync(join(MIGRATIONS_DIR, "meta", "_journal.json"), "utf8"));

/** A copy of the migrations folder that stops after the first `count` migrations. */
function migrationsUpTo(count: number): string {
  const dir = scratchFolder("migrations-");
  cpSync(MIGRATIONS_DIR, dir, { recursive: true });
  writeFileSync(
    join(dir, "meta", "_journal.json"),
    JSON.stringify({ ...journal, entries: journal.entries.slice(0, count) }),
  );
  return dir;
}

async function tables(url: string) {
  const sql = postgres(url, { max: 1, onnotice: () => {} });
  const rows = await sql`select table_name from information_schema.tables where table_schema = 'public' order by 1`;
  await sql.end();
  return rows.map((r) => r.table_name as string);
}

describe("migrations", () => {
  it("has at least two, so upgrades are exercised", () => {
    expect(journal.entries.length).toBeGreaterThanOrEqual(2);
  });

  it("migrate an empty database to the latest schema, and a second run changes nothing", async () => {
    const url = await freshDatabaseUrl(null);
    await migrateDatabase(url);
    const first = await tables(url);
    expect(first).toEqual(
      expect.arrayContaining([
        "studies",
        "experiments",
        "steps",
        "actions",
        "trials",
        "trial_events",
        "user",
        "session",
      ]),
    );
    await migrateDatabase(url);
    expect(await tables(url)).toEqual(first);
  });

  it.each(journal.entries.slice(1).map((e) => [e.tag, e.idx]))(
    "upgrades a database at the migration before %s, keeping its data",
    async (_tag, idx) => {
      const url = await freshDatabaseUrl(null);
      await migrateDatabase(url, migrationsUpTo(idx));
      const sql = postgres(url, { max: 1, onnotice: () => {} });
      await sql`insert into "user" (id, name, email) values ('u1', 'Ann', 'ann@example.org')`;
      await sql`insert into studies (id, title, created_by) values ('s1', 'Kept study', 'u1')`;
      await migrateDatabase(url);
      const [study] = await sql`select title, created_by from studies where id = 's1'`;
      await sql.end();
      expect(study).toEqual({ title: "Kept study", created_by: "u1" });
    },
  );
});
