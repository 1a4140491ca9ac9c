import { describe, expect, it } from "vitest";
import { oneAfterAnother, oneAfterAnotherBy } from "./one-after-another";

describe("one after another", () => {
  it("starts each of 1,000 jobs only once the one before settled, in the order given, a failure its own caller's", async () => {
    const inTurn = oneAfterAnother();
    const started: number[] = [];
    let running = 0;
    let most = 0;
    const results = Array.from({ length: 1000 }, (_, i) =>
      inTurn(async () => {
        started.push(i);
        most = Math.max(most, ++running);
        // Later jobs finish sooner if they ran together: they must not.
        await new Promise((r) => setTimeout(r, i % 3));
        running--;
        if (i % 7 === 0) throw new Error(`job ${i}`);
        return i;
      }).catch((error: Error) => error.message),
    );
    const settled = await Promise.all(results);
    expect(started).toEqual(Array.from({ length: 1000 }, (_, i) => i));
    expect(most).toBe(1);
    expect(settled).toEqual(Array.from({ length: 1000 }, (_, i) => (i % 7 === 0 ? `job ${i}` : i)));
  });

  it("keeps lanes apart", async () => {
    const [a, b] = [oneAfterAnother(), oneAfterAnother()];
    let release!: () => void;
    const held = a(() => new Promise<void>((r) => (release = r)));
    expect(await b(async () => "not held")).toBe("not held");
    release();
    await held;
  });

  it("keeps one lane per key: in order within a key, side by side across keys, each let go once idle", async () => {
    const inTurn = oneAfterAnotherBy<string>();
    const started: Record<string, number[]> = { a: [], b: [], c: [] };
    const running: Record<string, number> = { a: 0, b: 0, c: 0 };
    let mostPerKey = 0;
    let mostAtOnce = 0;
    const results = Array.from({ length: 300 }, (_, i) => {
      const key = "abc"[i % 3]!;
      return inTurn(key, async () => {
        started[key]!.push(i);
        mostPerKey = Math.max(mostPerKey, ++running[key]!);
        mostAtOnce = Math.max(mostAtOnce, running.a! + running.b! + running.c!);
        await new Promise((r) => setTimeout(r, (300 - i) % 4));
        running[key]!--;
        if (i % 11 === 0) throw new Error(`job ${i}`);
        return i;
      }).catch((error: Error) => error.message);
    });
    expect(inTurn.held()).toBe(3);
    const settled = await Promise.all(results);
    for (const [k, key] of ["a", "b", "c"].entries())
      expect(started[key]).toEqual(Array.from({ length: 100 }, (_, j) => 3 * j + k));
    expect(mostPerKey).toBe(1);
    expect(mostAtOnce).toBe(3);
    expect(settled).toEqual(Array.from({ length: 300 }, (_, i) => (i % 11 === 0 ? `job ${i}` : i)));
    expect(inTurn.held()).toBe(0);
  });
});
