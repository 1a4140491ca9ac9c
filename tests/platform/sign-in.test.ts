// Accounts at the HTTP edge: sign-in is rate limited, self sign-up is off
// unless a setting turns it on, and the API refuses callers without a session.
import { afterAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";

const post = (app: RunningApp, path: string, body: unknown) =>
  fetch(`${app.url}/api/auth${path}`, {
    method: "POST",
    headers: { "content-type": "application/json", origin: app.url },
    body: JSON.stringify(body),
  });

describe.sequential("sign-in and sign-up", () => {
  const apps: RunningApp[] = [];
  afterAll(async () => Promise.all(apps.map((a) => a.stop())));

  it("limits sign-in attempts per minute and says so", async () => {
    const app = await startApp({ env: { HRI_SIGNIN_PER_MINUTE: "3" } });
    apps.push(app);
    const statuses: number[] = [];
    for (let i = 0; i < 5; i++) {
      statuses.push((await post(app, "/sign-in/email", { email: "researcher@demo.hristudio", password: "wrong-password" })).status);
    }
    expect(statuses.slice(0, 3)).toEqual([401, 401, 401]);
    expect(statuses.slice(3)).toEqual([429, 429]);
    // Even the right password waits out the window.
    expect((await post(app, "/sign-in/email", { email: "researcher@demo.hristudio", password: DEMO_PASSWORD })).status).toBe(429);
  });

  it("refuses self sign-up by default, and the API refuses callers without a session", async () => {
    const app = await startApp();
    apps.push(app);
    const res = await post(app, "/sign-up/email", { name: "Eve", email: "eve@example.org", password: "long-enough-password" });
    expect(res.ok).toBe(false);
    await expect(apiClient(app.url).studies.mine.query()).rejects.toMatchObject({ data: { code: "UNAUTHORIZED" } });
  });

  it("allows self sign-up when HRI_ALLOW_SIGNUP is on, and a sign-up cannot choose its role", async () => {
    const app = await startApp({ env: { HRI_ALLOW_SIGNUP: "true" } });
    apps.push(app);
    const res = await post(app, "/sign-up/email", { name: "Eve", email: "eve@example.org", password: "long-enough-password", role: "administrator" });
    expect(res.ok).toBe(true);
    const cookie = await signIn(app.url, "eve@example.org", "long-enough-password");
    const eve = apiClient(app.url, cookie);
    expect((await eve.account.me.query())!.role).toBe("researcher");
    expect(await eve.studies.mine.query()).toEqual([]);
  });

  it("signs a disabled account out and keeps it out", async () => {
    const app = apps[1]!;
    const wizardCookie = await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD);
    const admin = apiClient(app.url, await signIn(app.url, "admin@demo.hristudio", DEMO_PASSWORD));
    const wizard = (await admin.admin.users.list.query()).find((u) => u.email === "wizard@demo.hristudio")!;
    await admin.admin.users.setDisabled.mutate({ userId: wizard.id, disabled: true });
    await expect(apiClient(app.url, wizardCookie).studies.mine.query()).rejects.toMatchObject({ data: { code: "UNAUTHORIZED" } });
    expect((await post(app, "/sign-in/email", { email: "wizard@demo.hristudio", password: DEMO_PASSWORD })).ok).toBe(false);
    await admin.admin.users.setDisabled.mutate({ userId: wizard.id, disabled: false });
    expect(await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD)).toContain("session_token");
  });
});
