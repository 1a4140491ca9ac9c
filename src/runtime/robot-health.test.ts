// A robot link's health on its record: each connection change written, and
// once the link is closed, one "disconnected" as it closes and nothing after
// (its socket's close, heard later, as the process stops); its listeners
// hear every change, that one too (the wizard's page says "released").
import { describe, expect, it } from "vitest";
import type { Database } from "@/store/client";
import type { RobotLink } from "./robot";
import { withHealth } from "./robot-health";

/** A link whose connection changes the test makes, and a database that keeps each robot-record update asked of it. */
function setUp() {
  const listeners: Array<(connected: boolean, detail?: string) => void> = [];
  const link = {
    onConnection: (listener: (connected: boolean, detail?: string) => void) => listeners.push(listener),
    watchState: () => () => {},
    close: () => {},
  } as unknown as RobotLink;
  const written: unknown[] = [];
  const db = {
    update: () => ({ set: (values: unknown) => ({ where: async () => void written.push(values) }) }),
  } as unknown as Database;
  const change = (connected: boolean) => listeners.forEach((l) => l(connected, connected ? undefined : "closed"));
  return { link: withHealth(db, "robot-1", link), change, written };
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
});
