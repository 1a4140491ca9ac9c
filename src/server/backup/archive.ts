// The backup file on disk: a tar archive written entry by entry without
// holding an entry in memory (its header is written last, once its size is
// known), and read back by an index of where each entry starts.
import { createReadStream } from "node:fs";
import { open, rename, rm, type FileHandle } from "node:fs/promises";
import { Readable } from "node:stream";
import { BLOCK, paddingAfter, readTarHeader, tarHeader } from "@/core/backup/tar";

export class BackupWriter {
  private at = 0;

  private constructor(
    private readonly file: FileHandle,
    private readonly path: string,
    private readonly partial: string,
  ) {}

  /** Written under a ".part" name and renamed when finished: a backup that stopped half way never looks whole. */
  static async create(path: string): Promise<BackupWriter> {
    const partial = `${path}.part`;
    return new BackupWriter(await open(partial, "w"), path, partial);
  }

  /** Adds one entry from its chunks; resolves to its size in bytes. */
  async add(name: string, chunks: AsyncIterable<Uint8Array> | Iterable<Uint8Array>): Promise<number> {
    const start = this.at;
    let size = 0;
    await this.write(new Uint8Array(BLOCK), start);
    for await (const chunk of chunks) {
      await this.write(chunk, start + BLOCK + size);
      size += chunk.byteLength;
    }
    await this.write(tarHeader(name, size, new Date()), start);
    this.at = start + BLOCK + size;
    await this.write(new Uint8Array(paddingAfter(size)), this.at);
    this.at += paddingAfter(size);
    return size;
  }

  /** Ends the archive (two zero blocks), makes it durable and gives it its name; resolves to its size. */
  async finish(): Promise<number> {
    await this.write(new Uint8Array(2 * BLOCK), this.at);
    await this.file.sync();
    await this.file.close();
    await rename(this.partial, this.path);
    return this.at + 2 * BLOCK;
  }

  /** After a failure: removes the half-written file. */
  async abandon() {
    await this.file.close().catch(() => {});
    await rm(this.partial, { force: true });
  }

  private async write(bytes: Uint8Array, position: number) {
    for (let done = 0; done < bytes.byteLength; ) {
      const { bytesWritten } = await this.file.write(bytes, done, bytes.byteLength - done, position + done);
      done += bytesWritten;
    }
  }
}

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

  has(name: string) {
    return this.entries.has(name);
  }

  /** The entry's bytes, read as the reader pulls. */
  stream(name: string): Readable {
    const entry = this.entry(name);
    if (entry.size === 0) return Readable.from([]);
    return createReadStream(this.path, { start: entry.offset, end: entry.offset + entry.size - 1 });
  }

  async bytes(name: string): Promise<Buffer> {
    const chunks: Buffer[] = [];
    for await (const chunk of this.stream(name)) chunks.push(chunk as Buffer);
    return Buffer.concat(chunks);
  }

  private entry(name: string) {
    const entry = this.entries.get(name);
    if (!entry)
      throw new Error(`The backup file ${this.path} has no "${name}": it is incomplete or not an HRIStudio backup.`);
    return entry;
  }
}
