// A robot link's health on its record: each connection change written, and
// once the link is closed, one "disconnected" as it closes and nothing after
// (its socket's close, heard later, as the process stops); its listeners
// hear every change, that one too (the wizard's page says "released").
import { describe, expect, it } from "vitest";
import type { Database } from "@/store/client";
import type { RobotLink } from "./robot";
import { robotHealth } from "./robot-health";

/**
 * A link whose connection changes the test makes, and a database that keeps each robot-record update asked of
 * it, once `answer` lets it (at once unless given).
 */
function setUp(answer: (n: number) => Promise<void> = async () => {}) {
  const listeners: Array<(connected: boolean, detail?: string) => void> = [];
  const link = {
    onConnection: (listener: (connected: boolean, detail?: string) => void) => listeners.push(listener),
    watchState: () => () => {},
    close: () => {},
  } as unknown as RobotLink;
  const written: unknown[] = [];
  let asked = 0;
  const db = {
    update: () => ({
      set: (values: unknown) => ({ where: () => answer(asked++).then(() => void written.push(values)) }),
    }),
  } as unknown as Database;
  const change = (connected: boolean) => listeners.forEach((l) => l(connected, connected ? undefined : "closed"));
  const health = robotHealth(db);
  return { link: health.withHealth("robot-1", link), change, written, health };
}

const connectedOf = (written: unknown[]) => written.map((w) => (w as { connected?: boolean }).connected);

describe("a robot link's health", () => {
  it("writes each change while open and nothing the socket says after it is closed, and tells them all", async () => {
    const { link, change, written } = setUp();
    const told: boolean[] = [];
    link.onConnection((connected) => told.push(connected));
    change(true);
    change(false);
    link.close();
    change(true);
    change(false);
    await new Promise((r) => setImmediate(r));
    expect(connectedOf(written)).toEqual([true, false, false]);
    expect(told).toEqual([true, false, true, false]);
  });

  it("writes a robot's changes in the order they happened, however slowly the first is answered", async () => {
    // The first write (connected) answered after the next (the link dropped) was asked for.
    const { change, written, health } = setUp((n) => new Promise((r) => setTimeout(r, n === 0 ? 50 : 0)));
    change(true);
    change(false);
    await health.settled();
    expect(connectedOf(written)).toEqual([true, false]);
  });

  it("settles once every write asked for is done: the runtime stopping waits for its links' last word", async () => {
    const { link, change, written, health } = setUp(() => new Promise((r) => setTimeout(r, 30)));
    change(true);
    link.close();
    await health.settled();
    expect(connectedOf(written)).toEqual([true, false]);
  });
});
