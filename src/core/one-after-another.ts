// Jobs run one after another, in the order they were given, each once the one
// before has settled: for work whose order matters (notices other processes
// read in order, a connection's replays, large designs that would take every
// core at once). One job's failure is its caller's, never the next one's.

/** A lane: each job given to it starts once every job given before has settled. */
export function oneAfterAnother() {
  let last: Promise<unknown> = Promise.resolve();
  return <T>(job: () => Promise<T>): Promise<T> => {
    const turn = last.then(job);
    last = turn.catch(() => {});
    return turn;
  };
}
