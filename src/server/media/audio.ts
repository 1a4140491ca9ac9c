// The study's audio files ("Play audio"): checked from their bytes, stored in
// the media store under the study, one row each. A file a published version
// plays stays: a published version must play the same sound every time.
import { createHash } from "node:crypto";
import { and, asc, eq, inArray, sql } from "drizzle-orm";
import type { DesignDraft } from "@/core/protocol/document";
import { audioFacts } from "@/core/media/audio-file";
import { MB } from "@/core/network/limits";
import type { Database } from "@/store/client";
import { experiments, experimentVersions, studyAudio } from "@/store/schema";
import type { MediaStorage } from "./storage";

/** Minutes of speech or music at any usual quality. */
export const AUDIO_LIMIT_BYTES = 20 * MB;
const MAX_NAME = 200;

export type StoredAudio = typeof studyAudio.$inferSelect;

/** The name a file is listed under: its own, without any folder, within the length the designer shows. */
export function audioName(raw: string | null): string {
  const base = (raw ?? "").split(/[\\/]/).pop()!.trim();
  return base.slice(0, MAX_NAME) || "sound";
}

/** Stores a sound for the study, or says why it is not one. */
export async function addAudio(
  db: Database,
  storage: MediaStorage,
  file: { studyId: string; userId: string; name: string; bytes: Uint8Array },
): Promise<{ ok: true; audio: StoredAudio } | { ok: false; reason: string }> {
  const facts = audioFacts(file.bytes);
  if (!facts)
    return {
      ok: false,
      reason: `“${file.name}” is not a WAV, MP3 or Ogg sound file (judged by its contents, not its name): convert it to one of these and upload it again.`,
    };
  const id = crypto.randomUUID();
  const storageKey = `audio/${file.studyId}/${id}.${facts.kind}`;
  await storage.put(storageKey, file.bytes, facts.mimeType);
  const [audio] = await db
    .insert(studyAudio)
    .values({
      id,
      studyId: file.studyId,
      name: file.name,
      mimeType: facts.mimeType,
      sizeBytes: file.bytes.length,
      sha256: createHash("sha256").update(file.bytes).digest("hex"),
      durationMs: facts.durationMs,
      storageKey,
      uploadedBy: file.userId,
    })
    .returning();
  return { ok: true, audio: audio! };
}

/** "version 2 of “Storyteller”" for each published version of the study that plays the file. */
export async function publishedUses(db: Pick<Database, "select">, studyId: string, audioId: string): Promise<string[]> {
  const rows = await db
    .select({ version: experimentVersions.version, experiment: experiments.name })
    .from(experimentVersions)
    .innerJoin(experiments, eq(experiments.id, experimentVersions.experimentId))
    .where(
      and(
        eq(experiments.studyId, studyId),
        sql`jsonb_path_exists(${experimentVersions.snapshot}, '$.steps[*].actions[*] ? (@.type == "play_audio" && @.parameters.fileId == $id)', jsonb_build_object('id', ${audioId}::text))`,
      ),
    )
    .orderBy(asc(experiments.name), asc(experimentVersions.version));
  return rows.map((r) => `version ${r.version} of “${r.experiment}”`);
}

/**
 * Why the design's sounds cannot be published: a file that is not one of the
 * study's, or whose bytes are not the ones chosen. The files are locked until
 * the publish commits, so none is deleted from under the new version.
 */
export async function soundProblems(tx: Pick<Database, "select">, studyId: string, draft: DesignDraft) {
  const plays = draft.steps.flatMap((step) =>
    step.actions.filter((a) => a.type === "play_audio").map((action) => ({ step, action })),
  );
  const ids = [...new Set(plays.map((p) => String(p.action.parameters.fileId ?? "")))];
  if (!ids.length) return [];
  const files = await tx
    .select({ id: studyAudio.id, sha256: studyAudio.sha256 })
    .from(studyAudio)
    .where(and(eq(studyAudio.studyId, studyId), inArray(studyAudio.id, ids)))
    .for("share");
  const byId = new Map(files.map((f) => [f.id, f.sha256]));
  return plays.flatMap(({ step, action }) => {
    const sha256 = byId.get(String(action.parameters.fileId ?? ""));
    const sound = `the sound “${String(action.parameters.name ?? "")}” in step “${step.name}”`;
    if (sha256 === undefined) return [`${sound} is not one of this study's sounds: choose it again.`];
    if (sha256 !== action.parameters.sha256) return [`${sound} has changed since it was chosen: choose it again.`];
    return [];
  });
}
