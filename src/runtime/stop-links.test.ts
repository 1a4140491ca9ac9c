// The stop links as the process stops: every link is closed, and a page that
// follows a trial from then on (its host closing under it) opens none, so
// nothing reads the database the process is closing.
import { describe, expect, it } from "vitest";
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
});
