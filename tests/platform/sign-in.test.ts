// Accounts at the HTTP edge: sign-in is limited per client address and per
// account, the address is the socket's (X-Forwarded-For counts only from a
// trusted proxy), self sign-up is off unless a setting turns it on, and the
// API refuses callers without a session.
//
// Each client below connects from its own loopback address (127.0.0.2,
// 127.0.0.3…), so the server sees really different sockets.
import { request } from "node:http";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";

interface Reply {
  status: number;
  message: string;
  cookie: string;
}

/** A POST to the auth API from the loopback address `from`, with any extra headers (X-Forwarded-For…). */
function post(
  app: RunningApp,
  path: string,
  body: unknown,
  options: { from?: string; headers?: Record<string, string> } = {},
): Promise<Reply> {
  const url = new URL(`${app.url}/api/auth${path}`);
  const payload = JSON.stringify(body);
  return new Promise((ok, fail) => {
    const req = request(
      url,
      {
        method: "POST",
        localAddress: options.from,
        headers: {
          "content-type": "application/json",
          "content-length": Buffer.byteLength(payload),
          origin: app.url,
          ...options.headers,
        },
      },
      (res) => {
        let text = "";
        res.on("data", (chunk) => (text += chunk));
        res.on("end", () => {
          const cookie = (res.headers["set-cookie"] ?? []).map((c) => c.split(";")[0]).join("; ");
          let message = "";
          try {
            message = (JSON.parse(text) as { message?: string }).message ?? "";
          } catch {
            // Not JSON: no message.
          }
          ok({ status: res.statusCode!, message, cookie });
        });
      },
    );
    req.on("error", fail);
    req.end(payload);
  });
}

const signInAs = (
  app: RunningApp,
  email: string,
  password: string,
  options: { from?: string; headers?: Record<string, string> } = {},
) => post(app, "/sign-in/email", { email, password }, options);

async function statuses(attempts: Array<() => Promise<Reply>>): Promise<number[]> {
  const result: number[] = [];
  for (const attempt of attempts) result.push((await attempt()).status);
  return result;
}

describe.sequential("sign-in and sign-up, with no trusted proxies (the default)", () => {
  let app: RunningApp;
  beforeAll(async () => {
    app = await startApp({ env: { HRI_SIGNIN_PER_MINUTE: "3" } });
  });
  afterAll(async () => app?.stop());

  it("limits sign-in attempts per address per minute and says so", async () => {
    const from = "127.0.0.2";
    const wrong = () => signInAs(app, "researcher@demo.hristudio", "wrong-password", { from });
    expect(await statuses([wrong, wrong, wrong, wrong, wrong])).toEqual([401, 401, 401, 429, 429]);
    // Even the right password waits out the window.
    expect((await signInAs(app, "researcher@demo.hristudio", DEMO_PASSWORD, { from })).status).toBe(429);
    // Another address has its own budget.
    expect((await signInAs(app, "researcher@demo.hristudio", DEMO_PASSWORD, { from: "127.0.0.3" })).status).toBe(200);
  });

  it("gives no extra attempts to a client that rotates X-Forwarded-For (or sends the server's own address header)", async () => {
    const rotating = [1, 2, 3, 4, 5].map(
      (i) => () =>
        signInAs(app, "rotation@example.org", "wrong-password", {
          from: "127.0.0.4",
          headers: { "x-forwarded-for": `203.0.113.${i}`, "x-hri-client-address": `198.51.100.${i}` },
        }),
    );
    expect(await statuses(rotating)).toEqual([401, 401, 401, 429, 429]);
  });

  it("does not let one client lock out the address it names in X-Forwarded-For", async () => {
    const spoofing = () =>
      signInAs(app, "spoof@example.org", "wrong-password", {
        from: "127.0.0.5",
        headers: { "x-forwarded-for": "127.0.0.6" },
      });
    expect(await statuses([spoofing, spoofing, spoofing, spoofing])).toEqual([401, 401, 401, 429]);
    // The address it named still has its whole budget.
    expect((await signInAs(app, "observer@demo.hristudio", DEMO_PASSWORD, { from: "127.0.0.6" })).status).toBe(200);
  });

  it("refuses self sign-up by default, and the API refuses callers without a session", async () => {
    const res = await post(app, "/sign-up/email", {
      name: "Eve",
      email: "eve@example.org",
      password: "long-enough-password",
    });
    expect(res.status).toBeGreaterThanOrEqual(400);
    await expect(apiClient(app.url).studies.mine.query()).rejects.toMatchObject({ data: { code: "UNAUTHORIZED" } });
  });

  it("signs a disabled account out and keeps it out", async () => {
    const from = { from: "127.0.0.7" };
    const wizardCookie = (await signInAs(app, "wizard@demo.hristudio", DEMO_PASSWORD, from)).cookie;
    const admin = apiClient(app.url, (await signInAs(app, "admin@demo.hristudio", DEMO_PASSWORD, from)).cookie);
    const wizard = (await admin.admin.users.list.query()).find((u) => u.email === "wizard@demo.hristudio")!;
    await admin.admin.users.setDisabled.mutate({ userId: wizard.id, disabled: true });
    await expect(apiClient(app.url, wizardCookie).studies.mine.query()).rejects.toMatchObject({
      data: { code: "UNAUTHORIZED" },
    });
    expect((await signInAs(app, "wizard@demo.hristudio", DEMO_PASSWORD, from)).status).not.toBe(200);
    await admin.admin.users.setDisabled.mutate({ userId: wizard.id, disabled: false });
    expect((await signInAs(app, "wizard@demo.hristudio", DEMO_PASSWORD, { from: "127.0.0.8" })).cookie).toContain(
      "session_token",
    );
  });
});

describe.sequential("sign-in behind a trusted proxy, and the per-account limit", () => {
  let app: RunningApp;
  // The tests connect from 127.0.0.1, playing the reverse proxy.
  beforeAll(async () => {
    app = await startApp({
      env: {
        HRI_TRUSTED_PROXIES: "127.0.0.1",
        HRI_SIGNIN_PER_MINUTE: "3",
        HRI_SIGNIN_ACCOUNT_FAILURES: "3",
        HRI_ALLOW_SIGNUP: "true",
      },
    });
  });
  afterAll(async () => app?.stop());

  const via = (forwardedFor: string) => ({ headers: { "x-forwarded-for": forwardedFor } });

  it("gives each forwarded client its own budget, keyed on the entry the proxy appended", async () => {
    // What a client wrote in front of the proxy's entry changes nothing.
    const first = [1, 2, 3, 4].map(
      (i) => () => signInAs(app, "first@example.org", "wrong-password", via(`9.9.9.${i}, 203.0.113.10`)),
    );
    expect(await statuses(first)).toEqual([401, 401, 401, 429]);
    const second = () => signInAs(app, "second@example.org", "wrong-password", via(`9.9.9.9, 203.0.113.11`));
    expect(await statuses([second])).toEqual([401]);
  });

  it("refuses an account after too many failures from several addresses, even with the right password; other accounts are unaffected", async () => {
    const attempt = (password: string, address: string, email = "researcher@demo.hristudio") =>
      signInAs(app, email, password, via(address));
    expect((await attempt("wrong-password", "198.51.100.1")).status).toBe(401);
    expect((await attempt("wrong-password", "198.51.100.2")).status).toBe(401);
    // The owner signing in meanwhile does not wipe the failures others left.
    expect((await attempt(DEMO_PASSWORD, "198.51.100.3")).status).toBe(200);
    expect((await attempt("wrong-password", "198.51.100.4")).status).toBe(401);

    const refused = await attempt(DEMO_PASSWORD, "198.51.100.5");
    expect(refused.status).toBe(429);
    expect(refused.message).toMatch(/^Too many failed sign-ins for this account; try again in \d+ minutes?\.$/);
    expect((await attempt(DEMO_PASSWORD, "198.51.100.6", "RESEARCHER@demo.hristudio")).status).toBe(429);
    expect((await attempt(DEMO_PASSWORD, "198.51.100.7", "observer@demo.hristudio")).status).toBe(200);
  });

  it("allows self sign-up when HRI_ALLOW_SIGNUP is on, and a sign-up cannot choose its role", async () => {
    const res = await post(app, "/sign-up/email", {
      name: "Eve",
      email: "eve@example.org",
      password: "long-enough-password",
      role: "administrator",
    });
    expect(res.status).toBe(200);
    const cookie = await signIn(app.url, "eve@example.org", "long-enough-password");
    const eve = apiClient(app.url, cookie);
    expect((await eve.account.me.query())!.role).toBe("researcher");
    expect(await eve.studies.mine.query()).toEqual([]);
  });
});
