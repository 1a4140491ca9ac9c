// A backup's rows into an empty database, in one transaction (all of it or
// nothing), parents before children, then the sequences where they were;
// `beforeCommit` (the media) runs inside it, so a failure there undoes the rows too.
import { pipeline } from "node:stream/promises";
import type postgres from "postgres";
import { formatBytes, tableFile, type BackupManifest } from "@/core/backup/manifest";
import type { BackupReader } from "./archive-reader";
import { fixTextFormats, quoteIdent } from "./catalog";

export async function loadDatabase(
  sql: postgres.Sql,
  reader: BackupReader,
  manifest: BackupManifest,
  progress: (line: string) => void,
  signal: AbortSignal,
  beforeCommit: () => Promise<void>,
) {
  await sql.begin(async (tx) => {
    await fixTextFormats(tx);
    for (const [i, table] of manifest.tables.entries()) {
      signal.throwIfAborted();
      const file = tableFile(table.name);
      progress(
        `tables ${i + 1}/${manifest.tables.length} (${table.name}): ${table.rows.toLocaleString("en")} rows, ${formatBytes(reader.size(file))}`,
      );
      if (table.rows === 0) continue;
      const rows = async () =>
        Number((await tx.unsafe<Array<{ n: string }>>(`SELECT count(*) AS n FROM ${quoteIdent(table.name)}`))[0]!.n);
      const before = await rows();
      try {
        const copy = await tx
          .unsafe(`COPY ${quoteIdent(table.name)} (${table.columns.map(quoteIdent).join(", ")}) FROM STDIN`)
          .writable();
        // The file is read as PostgreSQL takes it in: the writable's callbacks are the socket's.
        await pipeline(reader.stream(file), copy, { signal });
      } catch (error) {
        signal.throwIfAborted();
        throw new Error(
          `Could not load the table ${table.name}: ${error instanceof Error ? error.message : String(error)}`,
        );
      }
      // Each row the backup counted, no fewer: a file cut or damaged inside a table is refused here.
      const loaded = (await rows()) - before;
      if (loaded !== table.rows)
        throw new Error(
          `The table ${table.name} came back with ${loaded} rows where the backup counted ${table.rows}: the backup file is damaged.`,
        );
    }
    for (const s of manifest.sequences) {
      await tx`SELECT setval(${`public.${quoteIdent(s.name)}`}::regclass, ${s.value}::bigint, ${s.called})`;
    }
    await beforeCommit();
    signal.throwIfAborted();
  });
}
