// What arrived when on each topic the transport subscribed to, and what the
// bridge refused, checked now and then against the core's idea of silence
// (src/core/robots/silent-topics.ts). Kept per topic, not per subscription:
// the runtime subscribes to a state topic twice (the trial's samples and the
// robot's health), and the wizard is told once.
import { silence, SILENT_FLOOR_MS, type WatchedTopic } from "../../core/robots/silent-topics";

interface Watched extends WatchedTopic {
  /** The words last told for it; told again only once they change. */
  told: string | null;
}

export class TopicSilence {
  private readonly topics = new Map<string, Watched>();
  private timer: NodeJS.Timeout | null = null;

  constructor(
    private readonly tell: (problem: string) => void,
    private readonly floorMs = SILENT_FLOOR_MS,
  ) {}

  /** A subscribe sent on the live connection. */
  listening(topic: string, messageType: string, kind: WatchedTopic["kind"], throttleRate: number) {
    const known = this.topics.get(topic);
    if (known) {
      // Steady beats on demand: a topic both the trial and an action listen to is a state topic.
      if (kind === "state") Object.assign(known, { kind, throttleRate });
      return;
    }
    this.topics.set(topic, {
      topic,
      messageType,
      kind,
      throttleRate,
      since: Date.now(),
      lastAt: null,
      refused: null,
      waitedOut: false,
      told: null,
    });
    this.timer ??= setInterval(() => this.check(), Math.min(1000, this.floorMs / 4));
    this.timer.unref?.();
  }

  heard(topic: string) {
    const t = this.topics.get(topic);
    if (!t) return;
    Object.assign(t, { lastAt: Date.now(), refused: null, told: null });
  }

  refused(topic: string, text: string): boolean {
    const t = this.topics.get(topic);
    if (!t) return false;
    t.refused = text;
    this.check();
    return true;
  }

  waitedOut(topic: string) {
    const t = this.topics.get(topic);
    if (!t) return;
    t.waitedOut = true;
    this.check();
  }

  forget(topic: string) {
    this.topics.delete(topic);
  }

  /** A new connection: every subscription is sent again and its silence counted afresh. */
  reset() {
    this.topics.clear();
  }

  stop() {
    if (this.timer) clearInterval(this.timer);
    this.timer = null;
    this.topics.clear();
  }

  private check() {
    const now = Date.now();
    for (const t of this.topics.values()) {
      const said = silence(t, now, this.floorMs);
      if (!said || said === t.told) continue;
      t.told = said;
      this.tell(said);
    }
  }
}
