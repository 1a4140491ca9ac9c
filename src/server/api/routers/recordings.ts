// Recordings of a trial: started by the wizard's browser, filled chunk by
// chunk through /api/recordings/<id>/chunks/<n>, finished into one playable
// file, and played back on the analysis page.
import { TRPCError } from "@trpc/server";
import { and, asc, eq } from "drizzle-orm";
import { z } from "zod";
import { mediaRecordings } from "@/store/schema";
import { CHUNK_LIMIT_BYTES, fileKey, joinChunks, playable, RECORDING_TYPES } from "../../media/recordings";
import { router, studyProcedure } from "../trpc";
import { id } from "../validation";

const recordingId = z.object({ recordingId: id });

export const recordingsRouter = router({
  start: studyProcedure(
    "trial.run",
    "trial",
    z.object({
      trialId: id,
      kind: z.enum(["video", "audio"]),
      mimeType: z.string().max(200).regex(RECORDING_TYPES, "must be a WebM, MP4 or Ogg video or audio type"),
    }),
  ).mutation(async ({ ctx, input }) => {
    if (ctx.row.status === "completed" || ctx.row.status === "aborted")
      throw new TRPCError({
        code: "PRECONDITION_FAILED",
        message: "This trial has ended: there is nothing left to record.",
      });
    const recordingId = crypto.randomUUID();
    await ctx.db.insert(mediaRecordings).values({
      id: recordingId,
      trialId: ctx.row.id,
      kind: input.kind,
      mimeType: input.mimeType,
      storageKey: `recordings/${recordingId}`,
    });
    return { recordingId, chunkLimitBytes: CHUNK_LIMIT_BYTES };
  }),

  /** Recording start minus the trial's t0, as the recorder measured it. */
  setOffset: studyProcedure(
    "trial.run",
    "recording",
    recordingId.extend({ offsetMs: z.number().finite().min(-86_400_000).max(86_400_000) }),
  ).mutation(async ({ ctx, input }) => {
    await ctx.db.update(mediaRecordings).set({ offsetMs: input.offsetMs }).where(eq(mediaRecordings.id, ctx.row.id));
    return { offsetMs: input.offsetMs };
  }),

  /** Where the chunk route may write, for someone who may run the trial. */
  chunkTarget: studyProcedure("trial.run", "recording", recordingId).query(async ({ ctx }) => {
    const r = ctx.row;
    if (r.status !== "recording")
      throw new TRPCError({ code: "CONFLICT", message: "This recording is finished: it takes no more parts." });
    return { storageKey: r.storageKey, mimeType: r.mimeType };
  }),

  finish: studyProcedure(
    "trial.run",
    "recording",
    recordingId.extend({ durationMs: z.number().finite().min(0).max(86_400_000) }),
  ).mutation(async ({ ctx, input }) => {
    const r = ctx.row;
    if (r.status === "complete") return { recordingId: r.id, sizeBytes: r.sizeBytes };
    const { storage, maxBytes } = ctx.media;
    const joined = await joinChunks(storage, r.storageKey, maxBytes);
    const file = playable(joined, r.mimeType, input.durationMs);
    await storage.put(fileKey(r.storageKey, r.mimeType), file, r.mimeType);
    await ctx.db
      .update(mediaRecordings)
      .set({ status: "complete", sizeBytes: file.length, durationMs: input.durationMs, finishedAt: new Date() })
      .where(and(eq(mediaRecordings.id, r.id), eq(mediaRecordings.status, "recording")));
    // The parts go only once the whole file is safely stored.
    for (const key of await storage.list(`${r.storageKey}/`)) await storage.remove(key);
    return { recordingId: r.id, sizeBytes: file.length };
  }),

  list: studyProcedure("data.read", "trial", z.object({ trialId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: mediaRecordings.id,
        kind: mediaRecordings.kind,
        mimeType: mediaRecordings.mimeType,
        status: mediaRecordings.status,
        sizeBytes: mediaRecordings.sizeBytes,
        offsetMs: mediaRecordings.offsetMs,
        durationMs: mediaRecordings.durationMs,
      })
      .from(mediaRecordings)
      .where(eq(mediaRecordings.trialId, ctx.row.id))
      .orderBy(asc(mediaRecordings.createdAt)),
  ),

  /**
   * Where the finished file is, for the media route, which streams it from
   * storage in ranges: a recording never passes through the API whole.
   */
  media: studyProcedure("data.read", "recording", recordingId).query(async ({ ctx }) => {
    const r = ctx.row;
    if (r.status !== "complete")
      throw new TRPCError({ code: "PRECONDITION_FAILED", message: "This recording is not finished yet." });
    const storageKey = fileKey(r.storageKey, r.mimeType);
    const sizeBytes = await ctx.media.storage.size(storageKey);
    if (sizeBytes === null)
      throw new TRPCError({ code: "NOT_FOUND", message: "This recording's file is missing from media storage." });
    return { storageKey, mimeType: r.mimeType, sizeBytes };
  }),
});
