// A study's audio files: listed for the designer and the study page, added
// through /api/studies/<id>/audio (a binary upload), streamed to whoever
// plays them through /api/audio/<id>, and deleted unless a published version
// plays them.
import { TRPCError } from "@trpc/server";
import { asc, eq } from "drizzle-orm";
import { z } from "zod";
import { studyAudio } from "@/store/schema";
import { audit } from "../../audit";
import { AUDIO_LIMIT_BYTES, publishedUses } from "../../media/audio";
import { router, studyProcedure } from "../trpc";
import { id } from "../validation";

const audioFileId = z.object({ audioFileId: id });

export const audioRouter = router({
  list: studyProcedure("experiment.read", "study", z.object({ studyId: id })).query(({ ctx }) =>
    ctx.db
      .select({
        id: studyAudio.id,
        name: studyAudio.name,
        mimeType: studyAudio.mimeType,
        sizeBytes: studyAudio.sizeBytes,
        sha256: studyAudio.sha256,
        durationMs: studyAudio.durationMs,
        createdAt: studyAudio.createdAt,
      })
      .from(studyAudio)
      .where(eq(studyAudio.studyId, ctx.row.id))
      .orderBy(asc(studyAudio.name), asc(studyAudio.createdAt)),
  ),

  /** Whether the caller may add files to this study, for the upload route, and the most it takes. */
  uploadTarget: studyProcedure("experiment.edit", "study", z.object({ studyId: id })).query(({ ctx }) => ({
    studyId: ctx.row.id,
    limitBytes: Math.min(AUDIO_LIMIT_BYTES, ctx.media.maxBytes),
  })),

  remove: studyProcedure("experiment.edit", "audioFile", audioFileId).mutation(async ({ ctx }) => {
    const file = ctx.row;
    await ctx.db.transaction(async (tx) => {
      // Locked first: a publish that pins this file either commits before the check below or finds it gone.
      await tx.select({ id: studyAudio.id }).from(studyAudio).where(eq(studyAudio.id, file.id)).for("update");
      const uses = await publishedUses(tx, ctx.studyId, file.id);
      if (uses.length)
        throw new TRPCError({
          code: "CONFLICT",
          message: `“${file.name}” is played by ${uses.join(", ")}: a published version must play the same sound every time, so the file stays.`,
        });
      await tx.delete(studyAudio).where(eq(studyAudio.id, file.id));
      await audit(tx, {
        actorId: ctx.user.id,
        studyId: ctx.studyId,
        action: "audio.delete",
        target: file.id,
        details: { name: file.name, sha256: file.sha256 },
      });
    });
    // The row goes first: a file left behind by a failed removal is harmless, a row without its file is not.
    await ctx.media.storage.remove(file.storageKey);
    return { removed: file.id };
  }),

  /** Where the file is, for the route that streams it in ranges; whoever may run a trial plays it. */
  media: studyProcedure("trial.run", "audioFile", audioFileId).query(async ({ ctx }) => {
    const file = ctx.row;
    const sizeBytes = await ctx.media.storage.size(file.storageKey);
    if (sizeBytes === null)
      throw new TRPCError({ code: "NOT_FOUND", message: `The sound “${file.name}” is missing from media storage.` });
    return { storageKey: file.storageKey, mimeType: file.mimeType, sizeBytes, name: file.name };
  }),
});
