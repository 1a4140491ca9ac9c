// One connection's outbox: what goes at once, what waits a turn, what a full
// socket holds back, and a page too far behind closed (the server shuts it
// with 1013, "try again later": the browser reconnects and catches up).
import { describe, expect, it } from "vitest";
import { WELCOME_PART_BYTES } from "@/core/socket/welcome";
import { Outbox } from "./outbox";

const turn = () => new Promise((next) => setImmediate(next));

/** An outbox over a socket that records what it was given; `full` makes it answer -1 (Bun's "wait for drain"). */
function socket() {
  const sent: string[] = [];
  let behind = 0;
  const state = { full: false };
  const outbox = new Outbox(
    (text) => {
      sent.push(text);
      return state.full ? -1 : text.length;
    },
    () => behind++,
  );
  return { outbox, sent, state, behind: () => behind };
}

describe("a connection's outbox", () => {
  it("sends at once when nothing waits, and an observer's copy a turn later, after what is sent now", async () => {
    const { outbox, sent } = socket();
    outbox.send("ack");
    outbox.later("copy");
    outbox.send("after the copy");
    expect(sent).toEqual(["ack"]);
    await turn();
    expect(sent).toEqual(["ack", "copy", "after the copy"]);
    expect(outbox.idle).toBe(true);
  });

  it("sends a welcome's parts one turn at a time, a part's worth of bytes each, before anything after them", async () => {
    const { outbox, sent } = socket();
    const parts = Array.from({ length: 5 }, (_, i) => String(i).repeat(WELCOME_PART_BYTES));
    outbox.parts(parts);
    outbox.send("event after the welcome");
    for (let i = 1; i <= 5; i++) {
      await turn();
      expect(sent).toEqual(parts.slice(0, i));
    }
    await turn();
    expect(sent).toEqual([...parts, "event after the welcome"]);
  });

  it("holds everything back while the socket is full, and goes on, in order, once it drains", async () => {
    const { outbox, sent, state } = socket();
    state.full = true;
    outbox.send("first");
    outbox.send("second");
    outbox.later("third");
    await turn();
    await turn();
    expect(sent).toEqual(["first"]);
    expect(outbox.idle).toBe(false);
    state.full = false;
    outbox.drain();
    await turn();
    expect(sent).toEqual(["first", "second", "third"]);
  });

  it("gives up on a page more than 64 MB behind (a stalled browser), once, and sends it nothing more", async () => {
    const { outbox, sent, state, behind } = socket();
    state.full = true;
    outbox.send("the last it took");
    // A busy trial's batches, each 1 MB, for a browser that stopped reading.
    const batch = "x".repeat(1024 * 1024);
    for (let i = 0; i < 64; i++) outbox.send(batch);
    expect(behind()).toBe(0);
    outbox.send(batch);
    expect(behind()).toBe(1);
    state.full = false;
    outbox.drain();
    await turn();
    expect(sent).toEqual(["the last it took"]);
    expect(outbox.idle).toBe(true);
  });

  it("does not count a long welcome against a page: only what waits beyond it", async () => {
    const { outbox, state, behind } = socket();
    state.full = true;
    outbox.send("hello");
    outbox.parts(Array.from({ length: 100 }, () => "w".repeat(1024 * 1024)));
    outbox.send("x".repeat(1024 * 1024));
    expect(behind()).toBe(0);
  });
});
