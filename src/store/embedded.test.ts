// A restart after a crash stops the PostgreSQL server its folder's
// postmaster.pid names, and only that: a pid another program holds now is left
// alone, and the stale file goes so that our own server can start.
import { spawn } from "node:child_process";
import { existsSync, mkdirSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, describe, expect, it } from "vitest";
import { scratchFolder } from "../../tests/support/scratch";
import { freePort, portIsFree, startEmbeddedPostgres, stopOrphan } from "./embedded";

describe("a postmaster.pid left by a crash", () => {
  const stranger = spawn("sleep", ["60"], { stdio: "ignore" });
  const ended = new Promise<NodeJS.Signals | null>((ok) => stranger.once("exit", (_code, signal) => ok(signal)));
  afterAll(() => stranger.kill("SIGKILL"));

  it("naming another program's pid: leaves it running and removes the stale file", async () => {
    const pgDir = join(scratchFolder("orphan-"), "postgres");
    mkdirSync(pgDir);
    const pidFile = join(pgDir, "postmaster.pid");
    writeFileSync(pidFile, `${stranger.pid}\n${pgDir}\n1700000000\n5432\n`);

    expect(await stopOrphan(pgDir)).toBeNull();

    expect(existsSync(pidFile)).toBe(false);
    // Still running, untouched: the signal that ends it is the one sent now.
    stranger.kill("SIGKILL");
    expect(await ended).toBe("SIGKILL");
  });
});

describe("a port for a service of ours", () => {
  it("is one nothing listens on, and a port in use is never called free", async () => {
    const { createServer } = await import("node:net");
    const held = createServer();
    const port = await freePort();
    expect(await portIsFree(port)).toBe(true);
    await new Promise<void>((ok) => held.listen(port, "127.0.0.1", ok));
    try {
      expect(await portIsFree(port)).toBe(false);
    } finally {
      await new Promise((ok) => held.close(ok));
    }
    expect(await portIsFree(port)).toBe(true);
  });
});

describe("an embedded server stopped, then started again", () => {
  it("stops at the next stop, and leaves its folder to be removed", { timeout: 120_000 }, async () => {
    const dataDir = scratchFolder("restarted-");
    const pg = await startEmbeddedPostgres({ dataDir });
    const pidFile = join(dataDir, "postgres", "postmaster.pid");
    await pg.stop();
    expect(existsSync(pidFile)).toBe(false);
    await pg.restart();
    expect(existsSync(pidFile)).toBe(true);
    await pg.stop();
    // Stopped for good: no server left running past its stop, its pid file gone with it.
    expect(existsSync(pidFile)).toBe(false);
    expect(await portIsFree(pg.port)).toBe(true);
    rmSync(dataDir, { recursive: true, force: true });
  });
});
