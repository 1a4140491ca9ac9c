// A recording is finished once, into one file: by its recorder, which knows
// its length, or by the server from the parts it holds when the page that
// recorded it went away (cut off: its length read from its own frames). The
// row is locked meanwhile, so the two never finish it twice.
import { TRPCError } from "@trpc/server";
import { eq } from "drizzle-orm";
import { webmLastFrameMs } from "@/core/media/webm-duration";
import type { Database } from "@/store/client";
import { mediaRecordings, trials } from "@/store/schema";
import { chunkBytes, chunksToJoin, fileKey, playable } from "./recordings";
import type { MediaStorage } from "./storage";

export type Recording = typeof mediaRecordings.$inferSelect;
export type Media = { storage: MediaStorage; maxBytes: number };

/** `durationMs` as the recorder measured it, or "cut off": the server finishes what the page left. */
export async function finishRecording(
  db: Database,
  media: Media,
  recordingId: string,
  length: { durationMs: number } | "cut off",
): Promise<Recording | null> {
  const cutOff = length === "cut off";
  const finished = await db.transaction(async (tx) => {
    // The server skips a recording being finished already; its recorder waits for that to end.
    const [r] = await tx
      .select()
      .from(mediaRecordings)
      .where(eq(mediaRecordings.id, recordingId))
      .for("update", cutOff ? { skipLocked: true } : {});
    if (r?.status !== "recording") return r ?? null;
    let chunks: { keys: string[]; size: number };
    try {
      chunks = await chunksToJoin(media.storage, r.storageKey, media.maxBytes, { upToGap: cutOff });
    } catch (error) {
      // Nothing arrived, or too much: the server cannot make a file of it. It stays failed, its parts kept.
      if (!cutOff || !(error instanceof TRPCError)) throw error;
      const [failed] = await tx
        .update(mediaRecordings)
        .set({ status: "failed", cutOff, finishedAt: new Date() })
        .where(eq(mediaRecordings.id, r.id))
        .returning();
      return failed!;
    }
    const durationMs = cutOff ? await measuredLength(media.storage, chunks, r) : length.durationMs;
    // Streamed from its parts into one file: a recording of any length takes a part's memory.
    const file = await playable(media.storage, chunks, r.mimeType, durationMs);
    await media.storage.putStream(fileKey(r.storageKey, r.mimeType), file.bytes, file.size, r.mimeType);
    const [done] = await tx
      .update(mediaRecordings)
      .set({
        status: "complete",
        sizeBytes: file.size,
        durationMs,
        offsetMs: r.offsetMs ?? (cutOff ? await offsetFromCreation(tx, r) : null),
        cutOff,
        finishedAt: new Date(),
      })
      .where(eq(mediaRecordings.id, r.id))
      .returning();
    return done!;
  });
  // The parts go only once the whole file is safely stored and said so.
  if (finished?.status === "complete")
    for (const key of await media.storage.list(`${finished.storageKey}/`)) await media.storage.remove(key);
  return finished;
}

/**
 * A cut-off WebM's length is its last frame's time; another format's, the
 * time from its start to its last part. The walk over its frames reads what
 * arrived as one buffer (a cut-off WebM only; HRI_MEDIA_MAX_MB bounds it).
 */
async function measuredLength(storage: MediaStorage, chunks: { keys: string[] }, r: Recording): Promise<number> {
  const byClock = (r.lastPartAt ?? r.createdAt).getTime() - r.createdAt.getTime();
  if (!/webm/.test(r.mimeType)) return byClock;
  try {
    const parts: Uint8Array[] = [];
    for await (const part of chunkBytes(storage, chunks.keys)) parts.push(part);
    return webmLastFrameMs(Buffer.concat(parts)) ?? byClock;
  } catch {
    return byClock;
  }
}

/** The page closed before it said when recording began against t0: when it was started on the server is near enough. */
async function offsetFromCreation(tx: Pick<Database, "select">, r: Recording): Promise<number | null> {
  const [trial] = await tx.select({ t0: trials.t0 }).from(trials).where(eq(trials.id, r.trialId));
  return trial?.t0 ? r.createdAt.getTime() - trial.t0.getTime() : null;
}
