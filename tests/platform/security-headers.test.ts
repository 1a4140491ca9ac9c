// The security headers, on the real app as browsers meet it: a page, the API
// and a download. That the pages' policy still lets the app work (scripts,
// the trial socket, the recorder and the player) is proven by the browser
// suite, which runs every screen under it.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";

let app: RunningApp;
beforeAll(async () => {
  app = await startApp();
});
afterAll(() => app?.stop());

const COMMON = {
  "x-content-type-options": "nosniff",
  "referrer-policy": "same-origin",
  "x-frame-options": "DENY",
  "permissions-policy": expect.stringContaining("camera=(self), microphone=(self)"),
};

describe("security headers", () => {
  it("on a page: a policy that allows the trial runtime's socket (to someone signed in only) and no framing", async () => {
    const anonymous = await fetch(`${app.url}/sign-in`);
    expect(anonymous.status).toBe(200);
    expect(Object.fromEntries(anonymous.headers)).toMatchObject(COMMON);
    expect(anonymous.headers.get("content-security-policy")).toContain("connect-src 'self'; ");

    const cookie = await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD);
    const res = await fetch(`${app.url}/studies`, { headers: { cookie } });
    expect(res.status).toBe(200);
    expect(Object.fromEntries(res.headers)).toMatchObject(COMMON);
    const csp = res.headers.get("content-security-policy")!;
    expect(csp).toContain(`connect-src 'self' ${app.runtimeUrl}`);
    expect(csp).toContain("frame-ancestors 'none'");
    expect(csp).toContain("media-src 'self' blob:");
  });

  it("on the API and on a download: a policy that allows nothing", async () => {
    const api = await fetch(`${app.url}/api/trpc/studies.mine`);
    expect(api.status).toBe(401);
    expect(Object.fromEntries(api.headers)).toMatchObject({
      ...COMMON,
      "content-security-policy": expect.stringMatching(/^default-src 'none'; frame-ancestors 'none'/),
    });

    const cookie = await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD);
    const [study] = await apiClient(app.url, cookie).studies.mine.query();
    const download = await fetch(`${app.url}/api/studies/${study!.id}/questionnaires`, { headers: { cookie } });
    expect(download.status).toBe(200);
    expect(download.headers.get("content-type")).toMatch(/^text\/csv/);
    expect(Object.fromEntries(download.headers)).toMatchObject({
      ...COMMON,
      "content-security-policy": expect.stringMatching(/^default-src 'none'/),
    });
  });

  it("and over real HTTP, a body declared too large for the public form is refused unread", async () => {
    const res = await fetch(`${app.url}/api/trpc/form.save`, {
      method: "POST",
      headers: { "content-type": "application/json" },
      body: new Uint8Array(1024 * 1024),
    });
    expect(res.status).toBe(413);
    expect(await res.text()).toBe("A request to the public form may be at most 512 KB; this one is 1 MB.");
  });
});
