// Actions waiting for their done message (a plugin's "done_topic" completion
// rule). Each done topic is subscribed once, on first use, and kept for the
// transport's life (re-sent after every reconnect like any subscription), so
// a robot that answers quickly is not missed by a subscription made late.
import { fieldAt, matchesDone, valueKey, type DoneMatch } from "../../core/plugins";

export type DoneAnswer = { message: unknown } | "timeout" | "lost";

interface Waiter {
  match: DoneMatch | undefined;
  /** Listens across lost links (an action whose outcome is unknown): only its deadline or `cancel` end it. */
  outlivesLoss: boolean;
  /** When its wait began, among the transport's: the oldest waiter a message matches is the one it answers. */
  order: number;
  settle(answer: DoneAnswer): void;
}

type Subscribe = (topic: string, messageType: string, onMessage: (message: unknown) => void) => () => void;

/**
 * One done topic's waiting actions. Those whose match names the value they
 * expect (a say's "said: <text>") are found by that value, the others are
 * tried in turn: a robot speaking many lines has many waiting on one topic,
 * and a message that answers none of them (a line left over from the trial
 * before) costs a lookup, not a pass over them all.
 */
class Waiting {
  /** Every waiter, in the order their waits began. */
  readonly all = new Set<Waiter>();
  /** Field → the expected value's key → its waiters, in order. */
  private readonly byValue = new Map<string, Map<string, Set<Waiter>>>();
  private readonly tried = new Set<Waiter>();

  add(waiter: Waiter) {
    this.all.add(waiter);
    this.groupOf(waiter).add(waiter);
  }

  remove(waiter: Waiter) {
    if (!this.all.delete(waiter)) return;
    const group = this.groupOf(waiter);
    group.delete(waiter);
    const match = waiter.match;
    if (group.size === 0 && group !== this.tried && match) {
      const values = this.byValue.get(match.field)!;
      values.delete(valueKey(match.equals));
      if (values.size === 0) this.byValue.delete(match.field);
    }
  }

  /** The oldest waiter the message answers; an action sent since a lost link before one whose outcome is unknown. */
  answered(message: unknown): Waiter | undefined {
    const groups: Array<Set<Waiter>> = [this.tried];
    for (const [field, values] of this.byValue) {
      const group = values.get(valueKey(fieldAt(message, field)));
      if (group) groups.push(group);
    }
    for (const later of [false, true]) {
      let oldest: Waiter | undefined;
      for (const group of groups)
        for (const waiter of group) {
          if (oldest && waiter.order > oldest.order) break;
          if (waiter.outlivesLoss === later && matchesDone(waiter.match, message)) {
            oldest = waiter;
            break;
          }
        }
      if (oldest) return oldest;
    }
    return undefined;
  }

  private groupOf({ match }: Waiter): Set<Waiter> {
    if (match?.equals === undefined) return this.tried;
    let values = this.byValue.get(match.field);
    if (!values) this.byValue.set(match.field, (values = new Map()));
    const key = valueKey(match.equals);
    let group = values.get(key);
    if (!group) values.set(key, (group = new Set()));
    return group;
  }
}

export class DoneTopics {
  private readonly waiting = new Map<string, Waiting>();
  private began = 0;

  constructor(private readonly subscribe: Subscribe) {}

  /** Starts waiting before the action is sent; `cancel` ends the wait unanswered. */
  wait(topic: string, messageType: string, match: DoneMatch | undefined, deadline: number, outlivesLoss = false) {
    let waiting = this.waiting.get(topic);
    if (!waiting) {
      const fresh = new Waiting();
      this.waiting.set(topic, (waiting = fresh));
      this.subscribe(topic, messageType, (message) => fresh.answered(message)?.settle({ message }));
    }
    const set = waiting;
    let settle: (answer: DoneAnswer) => void = () => {};
    const answer = new Promise<DoneAnswer>((resolve) => {
      const timer = setTimeout(() => waiter.settle("timeout"), Math.max(0, deadline - Date.now()));
      const waiter: Waiter = {
        match,
        outlivesLoss,
        order: this.began++,
        settle: (a) => {
          clearTimeout(timer);
          set.remove(waiter);
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
    for (const { all: waiters } of this.waiting.values())
      [...waiters].forEach((w) => (all || !w.outlivesLoss) && w.settle("lost"));
  }
}
