// Media in a folder on the server (under HRI_DATA_DIR by default). A write
// goes to a temporary file, is flushed to disk, then renamed into place: a
// crash leaves the old bytes or the new ones, never half of either.
import { mkdir, open, readdir, readFile, rename, rm, stat } from "node:fs/promises";
import { dirname, join } from "node:path";
import type { ByteRange } from "@/core/media/byte-range";
import { type Chunks, checkKey, exactly, webStream, type MediaStorage } from "./storage";

const missing = (error: unknown) => (error as NodeJS.ErrnoException).code === "ENOENT";

export class LocalStorage implements MediaStorage {
  constructor(private readonly root: string) {}

  put(key: string, data: Uint8Array) {
    return this.putStream(key, [data], data.byteLength);
  }

  async putStream(key: string, data: Chunks, size: number) {
    const file = join(this.root, checkKey(key));
    await mkdir(dirname(file), { recursive: true });
    const temporary = `${file}.${process.pid}.${Date.now()}.part`;
    try {
      const handle = await open(temporary, "w");
      try {
        for await (const chunk of exactly(data, size, key))
          for (let done = 0; done < chunk.byteLength; )
            done += (await handle.write(chunk, done, chunk.byteLength - done)).bytesWritten;
        await handle.sync();
      } finally {
        await handle.close();
      }
      await rename(temporary, file);
    } catch (error) {
      await rm(temporary, { force: true });
      throw error;
    }
  }

  async get(key: string) {
    try {
      return await readFile(join(this.root, checkKey(key)));
    } catch (error) {
      if (missing(error)) return null;
      throw error;
    }
  }

  async size(key: string) {
    try {
      return (await stat(join(this.root, checkKey(key)))).size;
    } catch (error) {
      if (missing(error)) return null;
      throw error;
    }
  }

  async stream(key: string, range?: ByteRange) {
    // Opened here, so a missing file is null now rather than an error mid-stream.
    const handle = await open(join(this.root, checkKey(key)), "r").catch((error: unknown) => {
      if (missing(error)) return null;
      throw error;
    });
    if (!handle) return null;
    const file = handle.createReadStream(range ? { start: range.start, end: range.end } : {});
    return webStream(file);
  }

  async list(prefix: string) {
    const base = prefix.replace(/\/$/, "");
    if (base) checkKey(base);
    const entries = await readdir(join(this.root, base), { recursive: true, withFileTypes: true }).catch(
      (error: NodeJS.ErrnoException) => {
        if (error.code === "ENOENT") return [];
        throw error;
      },
    );
    return entries
      .filter((e) => e.isFile() && !e.name.endsWith(".part"))
      .map((e) => join(e.parentPath, e.name).slice(this.root.length + 1))
      .sort();
  }

  async remove(key: string) {
    await rm(join(this.root, checkKey(key)), { force: true });
  }
}
