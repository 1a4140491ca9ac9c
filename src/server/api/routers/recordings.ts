// Recordings of a trial: started by the wizard's browser, filled chunk by
// chunk through /api/recordings/<id>/chunks/<n>, finished into one playable
// file (by the recorder, or by the server when its page went away), and
// played back on the analysis page, part after part.
import { TRPCError } from "@trpc/server";
import { asc, eq, sql } from "drizzle-orm";
import { z } from "zod";
import { mediaRecordings } from "@/store/schema";
import { finishRecording } from "../../media/finish";
import { finishLeftOver, LAST_PART_MS } from "../../media/left-over";
import { CHUNK_LIMIT_BYTES, fileKey, RECORDING_TYPES } from "../../media/recordings";
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
    const r = await finishRecording(ctx.db, ctx.media, ctx.row.id, { durationMs: input.durationMs });
    return { recordingId: ctx.row.id, sizeBytes: r?.sizeBytes ?? 0 };
  }),

  /**
   * For the wizard's page as it opens: the trial's recordings a closed page
   * cut off (finished now if their recorder has been silent a little while).
   */
  cutOff: studyProcedure("trial.run", "trial", z.object({ trialId: id })).query(async ({ ctx }) => {
    await finishLeftOver(ctx.db, ctx.media, { trialId: ctx.row.id, quietMs: LAST_PART_MS });
    const rows = await ctx.db
      .select({
        id: mediaRecordings.id,
        status: mediaRecordings.status,
        cutOff: mediaRecordings.cutOff,
        durationMs: mediaRecordings.durationMs,
        stoppedAt: sql<Date>`coalesce(${mediaRecordings.lastPartAt}, ${mediaRecordings.createdAt})`.mapWith(
          mediaRecordings.createdAt,
        ),
      })
      .from(mediaRecordings)
      .where(eq(mediaRecordings.trialId, ctx.row.id))
      .orderBy(asc(mediaRecordings.createdAt));
    return rows.filter((r) => r.cutOff || r.status === "recording");
  }),

  list: studyProcedure("recording.read", "trial", z.object({ trialId: id })).query(async ({ ctx }) => {
    // Those whose page went away are finished first, so the trial's media is whole when it is looked at.
    await finishLeftOver(ctx.db, ctx.media, { trialId: ctx.row.id });
    return ctx.db
      .select({
        id: mediaRecordings.id,
        kind: mediaRecordings.kind,
        mimeType: mediaRecordings.mimeType,
        status: mediaRecordings.status,
        sizeBytes: mediaRecordings.sizeBytes,
        offsetMs: mediaRecordings.offsetMs,
        durationMs: mediaRecordings.durationMs,
        cutOff: mediaRecordings.cutOff,
      })
      .from(mediaRecordings)
      .where(eq(mediaRecordings.trialId, ctx.row.id))
      .orderBy(asc(mediaRecordings.createdAt));
  }),

  /**
   * Where the finished file is, for the media route, which streams it from
   * storage in ranges: a recording never passes through the API whole.
   */
  media: studyProcedure("recording.read", "recording", recordingId).query(async ({ ctx }) => {
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
