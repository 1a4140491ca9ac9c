// One client's subscription to one topic, shared by every subscribe id it
// sent for that topic (rosbridge keeps one per client and topic). The
// effective throttle_rate and queue_length are the smallest over the ids.
// Throttled without a queue, messages inside the interval are dropped;
// throttled with a queue, the newest waiting message goes out when the
// interval ends (transcript 03: every 5th message at 10 Hz and 500 ms).

export interface SubscribeOptions {
  throttleRate: number;
  queueLength: number;
}

export class Subscription {
  private readonly ids = new Map<string | null, SubscribeOptions>();
  private lastSent = -Infinity;
  private queue: Record<string, unknown>[] = [];
  private timer: NodeJS.Timeout | null = null;

  constructor(private readonly send: (message: Record<string, unknown>) => void) {}

  add(id: string | null, options: SubscribeOptions) {
    this.ids.set(id, options);
  }

  /** Without an id every subscribe id goes; with one, only that id (an unknown id changes nothing). */
  remove(id: string | null): boolean {
    if (id === null) this.ids.clear();
    else this.ids.delete(id);
    if (this.ids.size === 0) this.close();
    return this.ids.size === 0;
  }

  close() {
    if (this.timer) clearTimeout(this.timer);
    this.timer = null;
    this.queue = [];
  }

  private get options(): SubscribeOptions {
    const all = [...this.ids.values()];
    return {
      throttleRate: Math.min(...all.map((o) => o.throttleRate)),
      queueLength: Math.min(...all.map((o) => o.queueLength)),
    };
  }

  deliver(message: Record<string, unknown>) {
    const { throttleRate, queueLength } = this.options;
    const now = performance.now();
    if (throttleRate <= 0) return this.send(message);
    if (now - this.lastSent >= throttleRate && !this.timer) {
      this.lastSent = now;
      return this.send(message);
    }
    if (queueLength <= 0) return;
    this.queue.push(message);
    if (this.queue.length > queueLength) this.queue.shift();
    if (!this.timer) this.arm(throttleRate);
  }

  private arm(throttleRate: number) {
    this.timer = setTimeout(
      () => {
        this.timer = null;
        const next = this.queue.shift();
        if (!next) return;
        this.lastSent = performance.now();
        this.send(next);
        if (this.queue.length) this.arm(throttleRate);
      },
      Math.max(0, this.lastSent + throttleRate - performance.now()),
    );
  }
}
