import { describe, expect, it } from "vitest";
import { oneAfterAnother } from "./one-after-another";

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
});
