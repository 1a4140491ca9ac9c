// Robot state (joint angles, battery…) logged while trials run, timed on each
// trial's clock and written in batches: high-rate data never slows the
// wizard's events. One writer for every trial of a process: fifty trials'
// samples cost one commit every half second, not fifty. Written a trial at a
// time, their commits had met the wizards' appends in the database's disk
// flushes, all at once (trials started together flushed together).
import type { Database } from "@/store/client";
import { refusedByDatabase } from "@/store/client";
import { insertSamples, type SampleRow } from "@/store/samples";

const FLUSH_EVERY_MS = 500;
/** Rows that are written at once, not half a second on: a statement's size stays bounded whatever the robots send. */
const FLUSH_AT = 2000;

/** One trial's samples, into the process's writer. */
export interface SampleRecorder {
  add(topic: string, relMs: number, data: unknown): void;
  /** Writes what waits (every trial's) and resolves once it is stored or refused. */
  close(): Promise<void>;
}

export type SampleWriter = ReturnType<typeof sampleWriter>;

const notStored = (trialId: string, error: unknown) =>
  console.error(`[runtime] trial ${trialId}: samples not stored: ${String(error)}`);

/** `onError`: a trial's samples that were not stored, and why. */
export function sampleWriter(db: Database, onError: (trialId: string, error: unknown) => void = notStored) {
  let batch: SampleRow[] = [];
  let writing: Promise<void> = Promise.resolve();
  let due: ReturnType<typeof setTimeout> | null = null;
  // Refused as a whole (a trial deleted meanwhile, a message the database will not take): each trial's
  // rows are written again on their own, so one trial's refusal loses no other trial's samples.
  const store = async (rows: SampleRow[]) => {
    try {
      await insertSamples(db, rows);
    } catch (error) {
      const trials = new Map<string, SampleRow[]>();
      for (const row of rows) {
        const own = trials.get(row.trialId);
        if (own) own.push(row);
        else trials.set(row.trialId, [row]);
      }
      if (trials.size === 1 || !refusedByDatabase(error)) {
        for (const trialId of trials.keys()) onError(trialId, error);
        return;
      }
      for (const [trialId, own] of trials) await insertSamples(db, own).catch((e: unknown) => onError(trialId, e));
    }
  };
  const flush = () => {
    if (due) clearTimeout(due);
    due = null;
    if (!batch.length) return writing;
    const rows = batch;
    batch = [];
    writing = writing.then(() => store(rows));
    return writing;
  };
  return {
    recorder(trialId: string): SampleRecorder {
      return {
        add(topic, relMs, data) {
          batch.push({ trialId, topic, relMs, data });
          if (batch.length >= FLUSH_AT) void flush();
          // Armed by the first row to wait, so an idle process runs no timer.
          else due ??= setTimeout(() => void flush(), FLUSH_EVERY_MS);
        },
        close: flush,
      };
    },
  };
}
