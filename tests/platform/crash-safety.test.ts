// Nothing a request confirmed is lost when the app dies with kill -9, and the
// next start copes with whatever the dead one left behind.
import { existsSync } from "node:fs";
import { join } from "node:path";
import { afterAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";

describe.sequential("the app after kill -9", () => {
  let app: RunningApp | undefined;
  afterAll(async () => app?.stop());

  async function confirmedStudy(running: RunningApp, title: string) {
    const cookie = await signIn(running.url, "researcher@demo.hristudio", DEMO_PASSWORD);
    const created = await apiClient(running.url, cookie).studies.create.mutate({ title });
    return { id: created.id, cookie };
  }

  async function titlesAfterRestart(dataDir: string) {
    app = await startApp({ dataDir });
    const cookie = await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD);
    const studies = await apiClient(app.url, cookie).studies.mine.query();
    return studies.map((s) => s.title);
  }

  it("keeps a confirmed study when the launcher alone is killed (PostgreSQL and the web app orphaned)", async () => {
    app = await startApp();
    await confirmedStudy(app, "Confirmed before the launcher died");
    const { dataDir } = app;
    await app.crash("launcher");
    const titles = await titlesAfterRestart(dataDir);
    expect(titles).toContain("Confirmed before the launcher died");
    expect(titles).toContain("Storytelling and memory (demo)");
    expect(app.output()).toMatch(/Stopped (PostgreSQL left running|processes left)/);
  });

  it("keeps a confirmed study when every process is killed, PostgreSQL included", async () => {
    await confirmedStudy(app!, "Confirmed before everything died");
    const { dataDir } = app!;
    await app!.crash("everything");
    const titles = await titlesAfterRestart(dataDir);
    expect(titles).toEqual(
      expect.arrayContaining(["Confirmed before the launcher died", "Confirmed before everything died"]),
    );
    // The demo seed ran once, on the empty database only.
    expect(titles.filter((t) => t === "Storytelling and memory (demo)")).toHaveLength(1);
    expect(app!.output()).not.toContain("Demo accounts");
  });

  it("stops the embedded PostgreSQL cleanly on Ctrl+C", async () => {
    const { dataDir } = app!;
    await app!.stop();
    expect(existsSync(join(dataDir, "postgres", "postmaster.pid"))).toBe(false);
    expect(app!.output()).toContain("Stopping");
  });
});
