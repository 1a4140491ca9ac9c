// One connection's messages to its browser, in order. A message goes at once
// unless earlier ones still wait; what waits goes a turn of the event loop at
// a time, at most a welcome part's worth of bytes per turn, and not while the
// socket is backpressured (Bun's send returns -1; its drain handler resumes):
// a long welcome never holds the loop, and other trials' commands go between.
import { WELCOME_PART_BYTES } from "@/core/socket/welcome";

/** Bun's ServerWebSocket.send: -1 sent into a full buffer (wait for drain), 0 dropped (closed), else bytes sent. */
type Send = (text: string) => number;

/** What may wait for one connection, beyond its welcome: a browser further behind is closed, to catch up from the log. */
const WAITING_LIMIT_BYTES = 64 * 1024 * 1024;

export class Outbox {
  private readonly waiting: Array<{ text: string; counted: boolean }> = [];
  /** Bytes waiting, welcome parts aside. */
  private bytes = 0;
  private scheduled = false;
  private full = false;

  constructor(
    private readonly write: Send,
    /** Told once the connection is further behind than WAITING_LIMIT_BYTES. */
    private readonly behind: () => void,
  ) {}

  /** Nothing waits: a message sent now goes at once. */
  get idle(): boolean {
    return this.waiting.length === 0 && !this.full;
  }

  /** Now, unless earlier messages wait: then after them. */
  send(text: string) {
    if (this.idle) this.put(text);
    else this.queue(text, true);
  }

  /** On a later turn, after whatever is sent now (an observer's copy of the wizard's batch, after the wizard's ack). */
  later(text: string) {
    this.queue(text, true);
  }

  /** A welcome in parts: one turn at a time, before anything sent after it. */
  parts(texts: string[]) {
    for (const text of texts) this.queue(text, false);
  }

  /** Bun's drain: the socket's buffer has room again. */
  drain() {
    this.full = false;
    this.schedule();
  }

  close() {
    this.waiting.length = 0;
    this.bytes = 0;
  }

  private put(text: string) {
    if (this.write(text) === -1) this.full = true;
  }

  private queue(text: string, counted: boolean) {
    this.waiting.push({ text, counted });
    if (counted) this.bytes += text.length;
    if (this.bytes > WAITING_LIMIT_BYTES) {
      this.close();
      return this.behind();
    }
    this.schedule();
  }

  private schedule() {
    if (this.scheduled || this.full || this.waiting.length === 0) return;
    this.scheduled = true;
    setImmediate(() => {
      this.scheduled = false;
      this.turn();
    });
  }

  private turn() {
    let sent = 0;
    while (!this.full && this.waiting.length > 0 && sent < WELCOME_PART_BYTES) {
      const { text, counted } = this.waiting.shift()!;
      sent += text.length;
      if (counted) this.bytes -= text.length;
      this.put(text);
    }
    this.schedule();
  }
}
