// The database into the backup file: every table through COPY, inside one
// read-only REPEATABLE READ transaction, so what is written is one moment of
// the database even while trials run and append events.
import type postgres from "postgres";
import { tableFile, type BackupManifest } from "@/core/backup/manifest";
import { loadOrder } from "@/core/backup/table-order";
import type { BackupWriter } from "./archive";
import { appliedLevel, fixTextFormats, quoteIdent, referencesOf, sequencesOf, tablesOf } from "./catalog";
import { readJournal } from "./migrations";

type DatabasePart = Pick<BackupManifest, "migrations" | "tables" | "sequences">;

const NEWLINE = 0x0a;

/** Passes COPY's chunks through, counting rows: each ends in a newline (one inside a value is written as \n). */
async function* countingRows(chunks: AsyncIterable<Uint8Array>, count: { rows: number }) {
  for await (const chunk of chunks) {
    for (const byte of chunk) if (byte === NEWLINE) count.rows++;
    yield chunk;
  }
}

export async function dumpDatabase(
  sql: postgres.Sql,
  writer: BackupWriter,
  progress: (line: string) => void,
): Promise<DatabasePart> {
  return sql.begin("ISOLATION LEVEL REPEATABLE READ READ ONLY", async (tx) => {
    await fixTextFormats(tx);
    const migrations = await appliedLevel(tx, readJournal());
    const found = await tablesOf(tx);
    const order = loadOrder(
      found.map((t) => t.name),
      await referencesOf(tx),
    );
    const tables: DatabasePart["tables"] = [];
    for (const [i, name] of order.entries()) {
      progress(`tables ${i + 1}/${order.length} (${name})`);
      const { columns } = found.find((t) => t.name === name)!;
      const copy = await tx
        .unsafe(`COPY ${quoteIdent(name)} (${columns.map(quoteIdent).join(", ")}) TO STDOUT`)
        .readable();
      const count = { rows: 0 };
      await writer.add(tableFile(name), countingRows(copy, count));
      tables.push({ name, columns, rows: count.rows });
    }
    const sequences: DatabasePart["sequences"] = [];
    for (const name of await sequencesOf(tx)) {
      const [row] = await tx.unsafe<Array<{ value: string; called: boolean }>>(
        `SELECT last_value::text AS value, is_called AS called FROM ${quoteIdent(name)}`,
      );
      sequences.push({ name, value: row!.value, called: row!.called });
    }
    return { migrations, tables, sequences };
  }) as Promise<DatabasePart>;
}
