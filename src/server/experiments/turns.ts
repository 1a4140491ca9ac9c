// Large designs are imported, saved and published one at a time in each web
// server process. Three at once take every core there is, here and in
// PostgreSQL (two on a lab's small server), and everyone else's requests wait
// behind them; one at a time, the researchers who sent them wait a little
// longer instead. Small designs never wait.

import { oneAfterAnother } from "@/core/one-after-another";

/** A design of this many actions or more waits its turn: a tenth of the limit, under a second of work. */
export const LARGE_DESIGN = 5_000;
/** An experiment file this long holds about as many actions (40 characters each, written compactly). */
export const LARGE_FILE = LARGE_DESIGN * 40;

const largeDesigns = oneAfterAnother();

/** Runs `job` now, or for a large design after the large designs before it. */
export function inTurn<T>(large: boolean, job: () => Promise<T>): Promise<T> {
  return large ? largeDesigns(job) : job();
}
