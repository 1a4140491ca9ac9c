// Recordings whose page went away (closed, crashed) are finished by the server
// from the parts it holds: a recorder sends a part every few seconds, so one
// that has sent nothing for a while is gone. Looked for at the web server's
// start, every little while after, and when a trial's recordings are read.
import { and, eq, inArray, lt, or, sql } from "drizzle-orm";
import { logUnexpected } from "@/store/error-reference";
import type { Database } from "@/store/client";
import { mediaRecordings, trials } from "@/store/schema";
import { finishRecording, type Media, type Recording } from "./finish";

/** Silence after which a recorder is gone: its parts come every 3 s, and one cut off from the network resends for a while. */
export const GONE_AFTER_MS = 60_000;
/** After the trial's end (or for a wizard's page that opens anew), a recorder has this long to send its last part. */
export const LAST_PART_MS = 10_000;
const LOOK_EVERY_MS = 15_000;

const ENDED = ["completed", "aborted"] as const;

/**
 * Finishes the recordings left open: silent for GONE_AFTER_MS, or for
 * LAST_PART_MS once their trial has ended (`quietMs` shortens that, for one
 * trial whose wizard's page has just opened). Returns those it finished.
 */
export async function finishLeftOver(
  db: Database,
  media: Media,
  options: { now?: Date; trialId?: string; quietMs?: number } = {},
): Promise<Recording[]> {
  const now = (options.now ?? new Date()).getTime();
  const before = (ms: number) => new Date(now - ms);
  // Its last sign of life: its last part, or its start when none came.
  const silentFor = (ms: number) =>
    sql`coalesce(${mediaRecordings.lastPartAt}, ${mediaRecordings.createdAt}) < ${before(ms).toISOString()}`;
  const open = await db
    .select({ id: mediaRecordings.id })
    .from(mediaRecordings)
    .innerJoin(trials, eq(trials.id, mediaRecordings.trialId))
    .where(
      and(
        eq(mediaRecordings.status, "recording"),
        options.trialId ? eq(mediaRecordings.trialId, options.trialId) : undefined,
        or(
          silentFor(options.quietMs ?? GONE_AFTER_MS),
          and(inArray(trials.status, [...ENDED]), silentFor(LAST_PART_MS), lt(trials.endedAt, before(LAST_PART_MS))),
        ),
      ),
    );
  const finished: Recording[] = [];
  for (const { id } of open) {
    const done = await finishRecording(db, media, id, "cut off").catch((error: unknown) => {
      logUnexpected(error, `finishing the recording ${id}, whose page went away`);
      return null;
    });
    if (done) finished.push(done);
  }
  return finished;
}

/** The web server's watch: left-over recordings at once, then every LOOK_EVERY_MS. Returns its stop. */
export function keepFinishingLeftOver(db: Database, media: Media, log: (line: string) => void): () => void {
  // One look at a time: a slow one is not overtaken by the next.
  let looking = false;
  const look = () => {
    if (looking) return;
    looking = true;
    void finishLeftOver(db, media)
      .then((done) => {
        for (const r of done)
          log(
            r.status === "complete"
              ? `The recording ${r.id} (trial ${r.trialId}) was finished from its parts: the page recording it had gone.`
              : `The recording ${r.id} (trial ${r.trialId}) had no usable parts when its page went away: kept as failed.`,
          );
      })
      .catch((error: unknown) => void logUnexpected(error, "looking for recordings left open"))
      .finally(() => {
        looking = false;
      });
  };
  look();
  const timer = setInterval(look, LOOK_EVERY_MS);
  timer.unref();
  return () => clearInterval(timer);
}
