import { describe, expect, it } from "vitest";
import { arrivalOrder } from "./arrival-order";

const wait = (ms: number) => new Promise((r) => setTimeout(r, ms));

describe("arrival order", () => {
  it("lets 300 arrivals take effect in the order they arrived, whatever order their own waits end in", async () => {
    const turnOf = arrivalOrder(60_000);
    const took: number[] = [];
    await Promise.all(
      Array.from({ length: 300 }, async (_, i) => {
        const turn = turnOf("trial");
        // The first arrivals wait longest: done the other way round unless the turns hold them.
        await wait((300 - i) % 7);
        await turn.wait();
        took.push(i);
        turn.done();
      }),
    );
    expect(took).toEqual(Array.from({ length: 300 }, (_, i) => i));
  });

  it("lets the next go once one gives up, and keeps keys apart", async () => {
    const turnOf = arrivalOrder(60_000);
    const first = turnOf("a");
    const second = turnOf("a");
    const other = turnOf("b");
    let went = false;
    void second.wait().then(() => (went = true));
    // Another key's turn does not wait for this one's.
    await other.wait();
    await wait(1);
    expect(went).toBe(false);
    first.done();
    first.done();
    await second.wait();
    expect(went).toBe(true);
    second.done();
    other.done();
    // Nothing held: a new arrival goes at once.
    let fresh = false;
    void turnOf("a")
      .wait()
      .then(() => (fresh = true));
    await wait(0);
    expect(fresh).toBe(true);
  });

  it("lets a turn go after the most wait, whatever holds the one before", async () => {
    const turnOf = arrivalOrder(20);
    turnOf("a");
    const held = turnOf("a");
    let went = false;
    void held.wait().then(() => (went = true));
    await wait(5);
    expect(went).toBe(false);
    await expect.poll(() => went).toBe(true);
  });
});
