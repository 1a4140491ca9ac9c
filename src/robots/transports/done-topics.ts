// Actions waiting for their done message (a plugin's "done_topic" completion
// rule). Each done topic is subscribed once, on first use, and kept for the
// transport's life (re-sent after every reconnect like any subscription), so
// a robot that answers quickly is not missed by a subscription made late.
import { matchesDone, type DoneMatch } from "../../core/plugins";

export type DoneAnswer = { message: unknown } | "timeout" | "lost";

interface Waiter {
  match: DoneMatch | undefined;
  /** Listens across lost links (an action whose outcome is unknown): only its deadline or `cancel` end it. */
  outlivesLoss: boolean;
  settle(answer: DoneAnswer): void;
}

type Subscribe = (topic: string, messageType: string, onMessage: (message: unknown) => void) => () => void;

export class DoneTopics {
  private readonly waiters = new Map<string, Set<Waiter>>();

  constructor(private readonly subscribe: Subscribe) {}

  /** Starts waiting before the action is sent; `cancel` ends the wait unanswered. */
  wait(topic: string, messageType: string, match: DoneMatch | undefined, deadline: number, outlivesLoss = false) {
    let waiters = this.waiters.get(topic);
    if (!waiters) {
      const fresh = new Set<Waiter>();
      this.waiters.set(topic, (waiters = fresh));
      this.subscribe(topic, messageType, (message) => {
        // The oldest action this message matches is the one it answers (a set keeps the order waits began);
        // an action sent since a lost link before one whose outcome is unknown (it may never have arrived).
        // Two passes rather than a sorted copy: a robot speaking many lines has many waiting on one topic.
        for (const later of [false, true])
          for (const waiter of fresh)
            if (waiter.outlivesLoss === later && matchesDone(waiter.match, message)) return waiter.settle({ message });
      });
    }
    const set = waiters;
    let settle: (answer: DoneAnswer) => void = () => {};
    const answer = new Promise<DoneAnswer>((resolve) => {
      const timer = setTimeout(() => waiter.settle("timeout"), Math.max(0, deadline - Date.now()));
      const waiter: Waiter = {
        match,
        outlivesLoss,
        settle: (a) => {
          clearTimeout(timer);
          set.delete(waiter);
          resolve(a);
        },
      };
      settle = waiter.settle;
      set.add(waiter);
    });
    return { answer, cancel: () => settle("lost") };
  }

  /** The link is lost: no answer will come on it (`all`: the transport is closed, no answer will come at all). */
  lose(all = false) {
    for (const set of this.waiters.values()) [...set].forEach((w) => (all || !w.outlivesLoss) && w.settle("lost"));
  }
}
