import { describe, expect, it } from "vitest";
import { inTurn } from "./turns";

/** A job that notes when it starts and ends, and ends when told. */
function job(name: string, log: string[]) {
  let end!: () => void;
  const ended = new Promise<void>((resolve) => {
    end = resolve;
  });
  return {
    run: async () => {
      log.push(`${name} starts`);
      await ended;
      log.push(`${name} ends`);
      return name;
    },
    end: () => end(),
  };
}

describe("large designs take turns", () => {
  it("runs a large design after the one before it, and a small one at once", async () => {
    const log: string[] = [];
    const [first, second, small] = [job("first", log), job("second", log), job("small", log)];
    const firstDone = inTurn(true, first.run);
    const secondDone = inTurn(true, second.run);
    const smallDone = inTurn(false, small.run);
    small.end();
    expect(await smallDone).toBe("small");
    expect(log.toSorted()).toEqual(["first starts", "small ends", "small starts"]);
    first.end();
    second.end();
    expect(await Promise.all([firstDone, secondDone])).toEqual(["first", "second"]);
    expect(log.slice(3)).toEqual(["first ends", "second starts", "second ends"]);
  });

  it("goes on to the next after one that fails", async () => {
    const failed = inTurn(true, () => Promise.reject(new Error("refused")));
    await expect(failed).rejects.toThrow("refused");
    expect(await inTurn(true, async () => "next")).toBe("next");
  });
});
