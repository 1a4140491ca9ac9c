// The database into the backup file: every table through COPY, inside one
// read-only REPEATABLE READ transaction, so what is written is one moment of
// the database even while trials run and append events.
import type { Readable } from "node:stream";
import type postgres from "postgres";
import { formatBytes, tableFile, type BackupManifest } from "@/core/backup/manifest";
import { loadOrder } from "@/core/backup/table-order";
import type { BackupWriter } from "./archive";
import { appliedLevel, fixTextFormats, quoteIdent, referencesOf, sequencesOf, tablesOf } from "./catalog";
import { connectionLost } from "./database";
import { readJournal } from "./migrations";

type DatabasePart = Pick<BackupManifest, "migrations" | "tables" | "sequences">;

const NEWLINE = 0x0a;
/** How often a long table says how far it has come. */
const PROGRESS_EVERY_MS = 2000;

/** COPY's rows end in a newline (one inside a value is written as \n). */
function rowsIn(chunk: Uint8Array): number {
  let rows = 0;
  for (let at = chunk.indexOf(NEWLINE); at !== -1; at = chunk.indexOf(NEWLINE, at + 1)) rows++;
  return rows;
}

/**
 * One table's COPY into one entry. Each chunk is written synchronously as it
 * arrives, so the stream never holds one: postgres.js pauses its socket when
 * its stream's buffer is full and resumes it when read again, and under Bun
 * that resume can be lost (oven-sh/bun#10273), so a table past the buffer's
 * 64 KB stalled for good. The back-pressure is TCP's instead: while a chunk
 * is being written the socket is not read, and PostgreSQL waits.
 */
function copyInto(
  copy: Readable,
  writer: BackupWriter,
  name: string,
  say: (rows: number, bytes: number, done: boolean) => void,
  fail: (error: unknown) => void,
): Promise<{ rows: number; bytes: number }> {
  const entry = writer.begin();
  let rows = 0;
  let said = Date.now();
  let failed = false;
  return new Promise((resolve, reject) => {
    copy.on("data", (chunk: Uint8Array) => {
      if (failed) return; // The rest drains while the connection is closed.
      try {
        entry.write(chunk);
        rows += rowsIn(chunk);
      } catch (error) {
        failed = true;
        fail(error);
        return reject(error);
      }
      if (Date.now() - said < PROGRESS_EVERY_MS) return;
      said = Date.now();
      say(rows, entry.size, false);
    });
    copy.once("error", (error) => {
      // A lost connection ends the transaction itself; answering here would have postgres.js write a
      // rollback on the closed socket (a stack trace on the terminal).
      if (!connectionLost(error)) reject(error);
    });
    copy.once("end", () => {
      if (failed) return;
      const bytes = writer.end(tableFile(name), entry);
      say(rows, bytes, true);
      resolve({ rows, bytes });
    });
  });
}

export async function dumpDatabase(
  sql: postgres.Sql,
  writer: BackupWriter,
  progress: (line: string) => void,
  fail: (error: unknown) => void,
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
      const { columns } = found.find((t) => t.name === name)!;
      const say = (rows: number, bytes: number, done: boolean) =>
        progress(
          `tables ${i + 1}/${order.length} (${name}): ${rows.toLocaleString("en")} rows, ${formatBytes(bytes)}${done ? "" : " so far…"}`,
        );
      const copy = await tx
        .unsafe(`COPY ${quoteIdent(name)} (${columns.map(quoteIdent).join(", ")}) TO STDOUT`)
        .readable();
      const { rows } = await copyInto(copy, writer, name, say, fail);
      tables.push({ name, columns, rows });
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
