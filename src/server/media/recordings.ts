// A recording arrives in numbered chunks while the trial runs (each stored
// as it comes, so a crashed tab loses at most the last few seconds) and is
// joined into one file when it is finished, with its duration written in.
import { TRPCError } from "@trpc/server";
import { and, eq, sql } from "drizzle-orm";
import { withWebmDuration } from "@/core/media/webm-duration";
import type { Database } from "@/store/client";
import { mediaRecordings } from "@/store/schema";
import type { MediaStorage } from "./storage";

/** Larger than a few seconds of camera video at any sensible bitrate. */
export const CHUNK_LIMIT_BYTES = 16 * 1024 * 1024;
export const RECORDING_TYPES = /^(video|audio)\/(webm|mp4|ogg)(;.*)?$/;

export const chunkKey = (storageKey: string, index: number) => `${storageKey}/chunk-${String(index).padStart(6, "0")}`;
const extension = (mimeType: string) => (/mp4/.test(mimeType) ? "mp4" : /ogg/.test(mimeType) ? "ogg" : "webm");
export const fileKey = (storageKey: string, mimeType: string) => `${storageKey}.${extension(mimeType)}`;
/** The name a downloaded recording has, and the ELAN document links to. */
export const recordingFileName = (recordingId: string, mimeType: string) =>
  `recording-${recordingId}.${extension(mimeType)}`;

/** Notes that part `index` is stored: the recorder is still there (left-over.ts looks for those that are not). */
export async function partArrived(db: Database, recordingId: string, index: number) {
  await db
    .update(mediaRecordings)
    .set({ lastPartAt: new Date(), chunkCount: sql`greatest(${mediaRecordings.chunkCount}, ${index + 1})` })
    .where(and(eq(mediaRecordings.id, recordingId), eq(mediaRecordings.status, "recording")));
}

/**
 * The chunks to join, in order, and their size together. A gap (a chunk that
 * never arrived) is refused by naming it, for a recorder that will send it
 * again; `upToGap` takes those before it, for a recording whose recorder has gone.
 */
export async function chunksToJoin(
  storage: MediaStorage,
  storageKey: string,
  maxBytes: number,
  { upToGap = false } = {},
): Promise<{ keys: string[]; size: number }> {
  const stored = await storage.list(`${storageKey}/`);
  const index = (key: string) => Number(key.slice(key.lastIndexOf("-") + 1));
  const firstGap = stored.findIndex((key, i) => index(key) !== i);
  const keys = upToGap && firstGap !== -1 ? stored.slice(0, firstGap) : stored;
  if (!keys.length)
    throw new TRPCError({
      code: "PRECONDITION_FAILED",
      message: "No part of this recording arrived: nothing to finish.",
    });
  const indices = keys.map(index);
  const missing = indices.at(-1)! + 1 - indices.length;
  if (indices[0] !== 0 || missing > 0) {
    const gaps = Array.from({ length: indices.at(-1)! + 1 }, (_, i) => i).filter((i) => !indices.includes(i));
    throw new TRPCError({
      code: "PRECONDITION_FAILED",
      message: `Parts ${gaps.slice(0, 10).join(", ")} of this recording have not arrived yet; the recorder sends them again when it can.`,
    });
  }
  const size = (await Promise.all(keys.map((k) => storage.size(k)))).reduce<number>((n, s) => n + (s ?? 0), 0);
  if (size > maxBytes)
    throw new TRPCError({
      code: "PAYLOAD_TOO_LARGE",
      message: `This recording is ${(size / 1048576).toFixed(0)} MB; the limit is ${(maxBytes / 1048576).toFixed(0)} MB (HRI_MEDIA_MAX_MB).`,
    });
  return { keys, size };
}

async function chunk(storage: MediaStorage, key: string): Promise<Buffer> {
  const bytes = await storage.get(key);
  if (!bytes) throw new Error(`The part ${key} of this recording went missing while it was being finished.`);
  return bytes;
}

/** The chunks' bytes in order, one chunk in memory at a time. */
export async function* chunkBytes(storage: MediaStorage, keys: string[]): AsyncGenerator<Uint8Array> {
  for (const key of keys) yield await chunk(storage, key);
}

/**
 * The finished file as chunks, with its size. WebM gets its duration written
 * into its head (the first chunk, or the first few until they hold its Info),
 * so players can seek; other formats carry their own.
 */
export async function playable(
  storage: MediaStorage,
  chunks: { keys: string[]; size: number },
  mimeType: string,
  durationMs: number,
): Promise<{ size: number; bytes: AsyncIterable<Uint8Array> }> {
  if (!/webm/.test(mimeType)) return { size: chunks.size, bytes: chunkBytes(storage, chunks.keys) };
  let head = Buffer.alloc(0);
  for (const [i, key] of chunks.keys.entries()) {
    head = Buffer.concat([head, await chunk(storage, key)]);
    let patched: Uint8Array;
    try {
      patched = withWebmDuration(head, durationMs);
    } catch (error) {
      if (i === chunks.keys.length - 1) throw error;
      continue;
    }
    const rest = chunkBytes(storage, chunks.keys.slice(i + 1));
    async function* file() {
      yield patched;
      yield* rest;
    }
    return { size: chunks.size - head.length + patched.length, bytes: file() };
  }
  throw new Error("A recording with no parts cannot be finished.");
}
