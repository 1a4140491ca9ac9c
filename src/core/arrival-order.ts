// Things that arrive in an order and must take effect in it, though each first
// waits on something of its own that may come back in any order (a wizard's
// command reads the database before it enters its trial's queue: a recording's
// owner, a claim, the sender's access). Each takes a turn as it arrives, does
// its own waiting at once, and takes effect once every one that arrived before
// it has taken effect or given up. Keys (trials) are independent of each other.

export interface Turn {
  /** Settles once every turn taken before this one under the same key is done, or after the most wait. */
  wait: () => Promise<void>;
  /** This one took effect, or never will: the next may go. Called again, nothing. */
  done: () => void;
}

/** `mostWaitMs`: past it a turn goes whatever holds the ones before (a database that never answers them). */
export function arrivalOrder(mostWaitMs: number) {
  const last = new Map<string, Promise<void>>();
  return (key: string): Turn => {
    const before = last.get(key);
    let release!: () => void;
    const mine = new Promise<void>((ok) => (release = ok));
    last.set(key, mine);
    return {
      wait: () => {
        if (!before) return Promise.resolve();
        let timer: ReturnType<typeof setTimeout> | undefined;
        const late = new Promise<void>((ok) => (timer = setTimeout(ok, mostWaitMs)));
        return Promise.race([before, late]).finally(() => clearTimeout(timer));
      },
      done: () => {
        release();
        // The last turn under a key forgets it: a map of every trial ever commanded would only grow.
        if (last.get(key) === mine) last.delete(key);
      },
    };
  };
}
