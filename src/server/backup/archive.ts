// The backup file on disk: a tar archive written entry by entry without
// holding an entry in memory (its header is written last, once its size is
// known). archive-reader.ts reads it back.
import { closeSync, existsSync, fsyncSync, linkSync, openSync, renameSync, rmSync, writeSync } from "node:fs";
import { join } from "node:path";
import { backupName } from "@/core/backup/naming";
import { BLOCK, paddingAfter, tarHeader } from "@/core/backup/tar";

/** Where a backup goes: a file the researcher named, or a new name in a folder. */
export type BackupTarget = { file: string } | { folder: string; now: Date };

/** Bytes gathered before one write to disk: few writes for a table of small rows, little memory. */
const BUFFER = 1024 * 1024;

const code = (error: unknown) => (error as NodeJS.ErrnoException).code;

/** One entry being written: bytes go in as they come, synchronously (see dump.ts for why). */
export class EntryWriter {
  private held = 0;
  size = 0;

  constructor(
    private readonly archive: BackupWriter,
    private readonly start: number,
    /** The archive's one buffer: entries are written one at a time. */
    private readonly buffer: Uint8Array,
  ) {}

  write(chunk: Uint8Array) {
    if (this.held + chunk.byteLength > this.buffer.byteLength) this.flush();
    if (chunk.byteLength >= this.buffer.byteLength) this.archive.writeAt(chunk, this.start + BLOCK + this.size);
    else {
      this.buffer.set(chunk, this.held);
      this.held += chunk.byteLength;
    }
    this.size += chunk.byteLength;
  }

  flush() {
    this.archive.writeAt(this.buffer.subarray(0, this.held), this.start + BLOCK + this.size - this.held);
    this.held = 0;
  }
}

export class BackupWriter {
  private at = 0;
  private closed = false;
  private readonly buffer = new Uint8Array(BUFFER);

  private constructor(
    private readonly fd: number,
    /** The name it will have when finished. */
    readonly path: string,
    private readonly target: BackupTarget,
  ) {}

  /**
   * Written under a ".part" name, made with O_EXCL so two backups never write
   * one file, and given its name when finished: a backup that stopped half
   * way never looks whole. In a folder, a name already taken (by a file or a
   * backup under way) moves on to the next counter.
   */
  static create(target: BackupTarget): BackupWriter {
    if ("file" in target) return new BackupWriter(reserve(target.file, true)!, target.file, target);
    for (let attempt = 1; ; attempt++) {
      const path = join(target.folder, backupName(target.now, attempt));
      const fd = reserve(path, false);
      if (fd !== null) return new BackupWriter(fd, path, target);
    }
  }

  /** Starts an entry; end it with `end` before the next one. */
  begin(): EntryWriter {
    this.writeAt(new Uint8Array(BLOCK), this.at);
    return new EntryWriter(this, this.at, this.buffer);
  }

  /** Writes the entry's header now that its size is known; returns its size in bytes. */
  end(name: string, entry: EntryWriter): number {
    entry.flush();
    this.writeAt(tarHeader(name, entry.size, new Date()), this.at);
    this.at += BLOCK + entry.size;
    this.writeAt(new Uint8Array(paddingAfter(entry.size)), this.at);
    this.at += paddingAfter(entry.size);
    return entry.size;
  }

  /** Adds one entry from its chunks, pulling the next only once the last is written; resolves to its size. */
  async add(name: string, chunks: AsyncIterable<Uint8Array> | Iterable<Uint8Array>): Promise<number> {
    const entry = this.begin();
    for await (const chunk of chunks) entry.write(chunk);
    return this.end(name, entry);
  }

  /** Ends the archive (two zero blocks), makes it durable and gives it its name; resolves to its size. */
  finish(): number {
    this.writeAt(new Uint8Array(2 * BLOCK), this.at);
    fsyncSync(this.fd);
    this.close();
    publish(`${this.path}.part`, this.path, "file" in this.target);
    return this.at + 2 * BLOCK;
  }

  /** After a failure or an interruption: removes the half-written file. Safe to call twice. */
  abandon() {
    this.close();
    rmSync(`${this.path}.part`, { force: true });
  }

  writeAt(bytes: Uint8Array, position: number) {
    // Closed by abandon() while a COPY was still delivering: write nothing into a descriptor that may be reused.
    if (this.closed) throw new Error("The backup was stopped.");
    for (let done = 0; done < bytes.byteLength; )
      done += writeSync(this.fd, bytes, done, bytes.byteLength - done, position + done);
  }

  private close() {
    if (this.closed) return;
    this.closed = true;
    closeSync(this.fd);
  }
}

/** Opens `path.part` for a new backup; when the name is taken, null in a folder (try the next) or a plain refusal. */
function reserve(path: string, named: boolean): number | null {
  const refuse = (why: string) => {
    if (named) throw new Error(why);
    return null;
  };
  if (existsSync(path))
    return refuse(
      `There is a file at ${path} already: a backup never replaces a file. Choose another name, or move that file away first.`,
    );
  try {
    return openSync(`${path}.part`, "wx");
  } catch (error) {
    if (code(error) === "EEXIST")
      return refuse(
        `Another backup is being written to ${path}.part (or one was killed outright and left it: then remove it).`,
      );
    throw new Error(`Cannot write the backup at ${path}: ${(error as Error).message}`);
  }
}

/** Gives the finished file its name without replacing one that appeared meanwhile (a hard link fails if the name is taken). */
function publish(partial: string, path: string, named: boolean) {
  try {
    linkSync(partial, path);
    rmSync(partial);
  } catch (error) {
    if (code(error) === "EEXIST") {
      rmSync(partial, { force: true });
      throw new Error(
        `A file appeared at ${path} while the backup was written: it was left as it was, and this backup removed.${named ? "" : " Run the backup again."}`,
      );
    }
    // A file system without hard links (a FAT-formatted USB disk): the name was free when the backup began.
    if (code(error) === "EPERM" || code(error) === "ENOTSUP" || code(error) === "EOPNOTSUPP")
      return renameSync(partial, path);
    throw error;
  }
}
