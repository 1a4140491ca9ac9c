// The stop links as the process stops: every link is closed, and a page that
// follows a trial from then on (its host closing under it) opens none, so
// nothing reads the database the process is closing.
import { afterEach, describe, expect, it, vi } from "vitest";
import type { Database } from "@/store/client";
import { stopLinks } from "./stop-links";

/** A database that counts what is asked of it and answers nothing. */
function untouchedDatabase() {
  const asked = { count: 0 };
  const db = new Proxy({} as Database, {
    get() {
      asked.count++;
      throw new Error("the database was read");
    },
  });
  return { db, asked };
}

describe("stop links as the process stops", () => {
  afterEach(() => vi.restoreAllMocks());

  it("opens no link once closed: the database is never read", () => {
    const { db, asked } = untouchedDatabase();
    let links = 0;
    const stops = stopLinks(db, () => {
      links++;
      return null;
    });
    stops.closeAll();
    const release = stops.hold("a-trial");
    release();
    expect(asked.count).toBe(0);
    expect(links).toBe(0);
    expect(stops.halt("a-trial")).toBe(false);
  });

  it("says nothing of a read the closing cut off, and logs one that failed while the link was wanted", async () => {
    const logged = vi.spyOn(console, "error").mockImplementation(() => {});
    const { db, asked } = untouchedDatabase();
    const stops = stopLinks(db, () => null);
    // Held as the trial's host closed, then the process stops while the link is read.
    stops.hold("closing-trial");
    stops.closeAll();
    await new Promise((r) => setTimeout(r, 0));
    expect(asked.count).toBe(1);
    expect(logged).not.toHaveBeenCalled();

    const open = stopLinks(untouchedDatabase().db, () => null);
    open.hold("open-trial");
    await new Promise((r) => setTimeout(r, 0));
    expect(logged).toHaveBeenCalledTimes(1);
    expect(String(logged.mock.calls[0]![0])).toContain("opening a robot link to stop");
  });
});
