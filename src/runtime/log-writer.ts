// Group commit: every trial host of this process appends through one writer.
// While a commit is under way, what arrives waits, and all of it goes in the
// next statement: N trials' events cost one commit, not N. Each append still
// resolves only once its own commit is done, with its own events, so nothing
// is acknowledged before it is stored. An append may be given as a function,
// called as its commit is made up: what its trial learns until then (a
// robot's completion right after the dispatch) is written in the same commit.
import type { StoredEvent } from "@/core/trial";
import { type Database, refusedByDatabase } from "@/store/client";
import { type Append, appendMany } from "@/store/event-store";

/** An append, or one made up only when its commit is (its events decided as late as can be). */
export type LateAppend = Append | (() => Append);

export interface LogWriter {
  /** A trial has one append under way at most (its host writes in turn): a commit moves each trial once. */
  append(append: LateAppend): Promise<StoredEvent[]>;
}

const madeUp = (append: LateAppend): Append => (typeof append === "function" ? append() : append);

/** One statement per append: for a host on its own (tests, tools). */
export function directWriter(db: Database): LogWriter {
  return { append: async (append) => (await appendMany(db, [madeUp(append)]))[0]! };
}

/** Bounds one statement's size; a longer queue is written in several commits, in order. */
const MOST_PER_COMMIT = 500;

export function groupWriter(db: Database): LogWriter {
  type Waiting = { append: LateAppend; done: (events: StoredEvent[]) => void; fail: (error: unknown) => void };
  const waiting: Waiting[] = [];
  let writing = false;

  async function writeAll() {
    writing = true;
    while (waiting.length) {
      const batch: Array<Waiting & { made: Append }> = [];
      // One append that cannot be made up fails alone: the writer carries on for every other trial.
      for (const w of waiting.splice(0, MOST_PER_COMMIT)) {
        try {
          batch.push({ ...w, made: madeUp(w.append) });
        } catch (error) {
          w.fail(error);
        }
      }
      if (!batch.length) continue;
      try {
        const stored = await appendMany(
          db,
          batch.map((w) => w.made),
        );
        batch.forEach((w, i) => w.done(stored[i]!));
      } catch (error) {
        // Refused by the server, the whole statement rolled back: one trial's refusal (a stale cursor)
        // must not fail the others, so each is written again alone and meets its own outcome. A lost
        // connection leaves the outcome unknown: each host finds out from its log.
        if (batch.length === 1 || !refusedByDatabase(error)) for (const w of batch) w.fail(error);
        else await Promise.all(batch.map((w) => appendMany(db, [w.made]).then(([events]) => w.done(events!), w.fail)));
      }
    }
    writing = false;
  }

  return {
    append: (append) =>
      new Promise((done, fail) => {
        waiting.push({ append, done, fail });
        if (!writing) void writeAll();
      }),
  };
}
