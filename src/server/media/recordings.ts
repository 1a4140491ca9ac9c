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
 * Joins the chunks in order. A gap (a chunk that never arrived) is refused by
 * naming it, for a recorder that will send it again; `upToGap` joins those
 * before it, for a recording whose recorder has gone.
 */
export async function joinChunks(
  storage: MediaStorage,
  storageKey: string,
  maxBytes: number,
  { upToGap = false } = {},
): Promise<Uint8Array> {
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
  const parts = await Promise.all(keys.map((k) => storage.get(k)));
  const size = parts.reduce((n, p) => n + (p?.length ?? 0), 0);
  if (size > maxBytes)
    throw new TRPCError({
      code: "PAYLOAD_TOO_LARGE",
      message: `This recording is ${(size / 1048576).toFixed(0)} MB; the limit is ${(maxBytes / 1048576).toFixed(0)} MB (HRI_MEDIA_MAX_MB).`,
    });
  const joined = new Uint8Array(size);
  let at = 0;
  for (const part of parts) {
    joined.set(part!, at);
    at += part!.length;
  }
  return joined;
}

/** WebM gets its duration written in, so players can seek; other formats carry their own. */
export function playable(bytes: Uint8Array, mimeType: string, durationMs: number): Uint8Array {
  return /webm/.test(mimeType) ? withWebmDuration(bytes, durationMs) : bytes;
}
