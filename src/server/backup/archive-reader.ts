// The backup file read back: an index of where each entry starts, built from
// the tar headers, and each entry streamed or read from there.
import { createReadStream } from "node:fs";
import { open } from "node:fs/promises";
import { Readable } from "node:stream";
import { BLOCK, paddingAfter, readTarHeader } from "@/core/backup/tar";

export class BackupReader {
  private constructor(
    private readonly path: string,
    private readonly entries: Map<string, { offset: number; size: number }>,
  ) {}

  static async open(path: string): Promise<BackupReader> {
    const file = await open(path, "r").catch((error: NodeJS.ErrnoException) => {
      throw new Error(
        error.code === "ENOENT"
          ? `There is no backup file at ${path}.`
          : `Cannot read the backup file ${path}: ${error.message}`,
      );
    });
    const entries = new Map<string, { offset: number; size: number }>();
    try {
      const { size: fileSize } = await file.stat();
      for (let at = 0; ; ) {
        if (at >= fileSize)
          throw new Error(
            `The backup file ${path} ends before its last entry: it is incomplete (was it copied in full?).`,
          );
        const block = new Uint8Array(BLOCK);
        const { bytesRead } = await file.read(block, 0, BLOCK, at);
        const header = readTarHeader(block.subarray(0, bytesRead), at);
        if (!header) break;
        if (at + BLOCK + header.size > fileSize)
          throw new Error(
            `The backup file ${path} ends inside "${header.name}": it is incomplete (was it copied in full?).`,
          );
        if (header.type === "0") entries.set(header.name, { offset: at + BLOCK, size: header.size });
        at += BLOCK + header.size + paddingAfter(header.size);
      }
    } finally {
      await file.close();
    }
    return new BackupReader(path, entries);
  }

  size(name: string) {
    return this.entry(name).size;
  }

  /** The entry's bytes, read as the reader pulls. */
  stream(name: string): Readable {
    const entry = this.entry(name);
    if (entry.size === 0) return Readable.from([]);
    return createReadStream(this.path, { start: entry.offset, end: entry.offset + entry.size - 1 });
  }

  async bytes(name: string): Promise<Buffer> {
    return Buffer.from(await this.readInto(name, new Uint8Array(this.entry(name).size)));
  }

  /** The entry's bytes read into `buffer` (at least the entry's size). */
  private async readInto(name: string, buffer: Uint8Array): Promise<Uint8Array> {
    const { offset, size } = this.entry(name);
    const file = await open(this.path, "r");
    try {
      for (let done = 0; done < size; ) {
        const { bytesRead } = await file.read(buffer, done, size - done, offset + done);
        if (bytesRead === 0) throw new Error(`The backup file ${this.path} ends inside "${name}": it is incomplete.`);
        done += bytesRead;
      }
    } finally {
      await file.close();
    }
    return buffer.subarray(0, size);
  }

  private entry(name: string) {
    const entry = this.entries.get(name);
    if (!entry)
      throw new Error(`The backup file ${this.path} has no "${name}": it is incomplete or not an HRIStudio backup.`);
    return entry;
  }
}
