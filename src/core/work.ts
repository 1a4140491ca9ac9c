// Long work in the core (a design of 50,000 actions checked, read or hashed)
// is written as a generator that yields between pieces of it, a step of the
// design say. The core stays free of timers: the server runs such work a
// slice of time at a time so other people's requests are served in between
// (src/store/sliced.ts); a test or the browser runs it straight through.
export type Work<T> = Generator<void, T, void>;

/** Runs the work to its end at once. */
export function finish<T>(work: Work<T>): T {
  for (;;) {
    const next = work.next();
    if (next.done) return next.value;
  }
}
