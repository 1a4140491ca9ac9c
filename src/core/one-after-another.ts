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

/**
 * A lane per key (a trial's): jobs of one key one after another, of different keys side by side; a key's lane
 * is let go once its last job has settled, so a long-running process holds only the lanes in use.
 */
export function oneAfterAnotherBy<K>() {
  const lanes = new Map<K, { inTurn: ReturnType<typeof oneAfterAnother>; jobs: number }>();
  const by = <T>(key: K, job: () => Promise<T>): Promise<T> => {
    const lane = lanes.get(key) ?? { inTurn: oneAfterAnother(), jobs: 0 };
    lanes.set(key, lane);
    lane.jobs++;
    return lane.inTurn(job).finally(() => {
      if (--lane.jobs === 0) lanes.delete(key);
    });
  };
  return Object.assign(by, { held: () => lanes.size });
}
