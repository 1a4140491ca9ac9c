// Where recordings live: a local folder by default, MinIO or any S3-compatible
// server when configured. One interface, one contract test suite for both.
// Keys are relative paths of safe characters; nothing can climb out.
import { Readable } from "node:stream";
import type { ByteRange } from "@/core/media/byte-range";

/** Bytes in chunks: a Node stream, a generator, an array. */
export type Chunks = AsyncIterable<Uint8Array> | Iterable<Uint8Array>;

export interface MediaStorage {
  /** Stores bytes under a key, replacing what was there; durable when it resolves. */
  put(key: string, data: Uint8Array, contentType: string): Promise<void>;
  /**
   * Stores `size` bytes read from `data` as it yields them, pulling the next
   * chunk only once the last is written (a recording of any length takes a
   * chunk's memory, or one upload part's). The object appears whole when it
   * resolves, or not at all: a stream that fails, or yields other than `size`
   * bytes, leaves what was under the key as it was.
   */
  putStream(key: string, data: Chunks, size: number, contentType: string): Promise<void>;
  /** The bytes under a key, or null when there are none. */
  get(key: string): Promise<Buffer | null>;
  /** The size in bytes of what is under a key, or null when there is nothing. */
  size(key: string): Promise<number | null>;
  /**
   * The bytes under a key as a stream, read as the reader pulls (a whole
   * recording is never held in memory): all of them, or the range's first to
   * last byte. Null when there is nothing under the key.
   */
  stream(key: string, range?: ByteRange): Promise<ReadableStream<Uint8Array> | null>;
  /** Keys under a prefix, in order. */
  list(prefix: string): Promise<string[]>;
  remove(key: string): Promise<void>;
}

const SAFE_KEY = /^[A-Za-z0-9][A-Za-z0-9._-]*(\/[A-Za-z0-9][A-Za-z0-9._-]*)*$/;

/** Refuses a key that could escape the storage root or name something odd, saying which. */
export function checkKey(key: string): string {
  if (key.length > 500 || !SAFE_KEY.test(key) || key.split("/").some((part) => part === "." || part === "..")) {
    throw new Error(
      `"${key.slice(0, 80)}" is not a valid media key (letters, digits, ".", "_", "-" in parts separated by "/")`,
    );
  }
  return key;
}

/** The stream's chunks, refused in plain words once it proves longer or shorter than it was said to be. */
export async function* exactly(data: Chunks, size: number, key: string) {
  let seen = 0;
  const refuse = () =>
    new Error(
      `The bytes for the media file "${key}" were ${seen > size ? "more" : "fewer"} than the ${size} expected.`,
    );
  for await (const chunk of data) {
    seen += chunk.byteLength;
    if (seen > size) throw refuse();
    yield chunk;
  }
  if (seen !== size) throw refuse();
}

/** A Node stream as the web stream both stores hand out (Node's and the DOM's stream types differ only on paper). */
export const webStream = (body: Readable) => Readable.toWeb(body) as unknown as ReadableStream<Uint8Array>;
