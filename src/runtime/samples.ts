// Robot state (joint angles, battery…) logged while a trial runs, timed on
// the trial's clock and written in batches: high-rate data never slows the
// wizard's events.
import type { Database } from "@/store/client";
import { trialSamples } from "@/store/schema";

const FLUSH_EVERY_MS = 500;
const FLUSH_AT = 500;

export function sampleRecorder(db: Database, trialId: string, onError: (error: unknown) => void) {
  let batch: Array<typeof trialSamples.$inferInsert> = [];
  let writing: Promise<void> = Promise.resolve();
  const flush = () => {
    if (!batch.length) return writing;
    const rows = batch;
    batch = [];
    writing = writing.then(() =>
      db
        .insert(trialSamples)
        .values(rows)
        .then(() => undefined, onError),
    );
    return writing;
  };
  const timer = setInterval(() => void flush(), FLUSH_EVERY_MS);
  return {
    add(topic: string, relMs: number, data: unknown) {
      batch.push({ trialId, topic, relMs, data });
      if (batch.length >= FLUSH_AT) void flush();
    },
    async close() {
      clearInterval(timer);
      await flush();
    },
  };
}
