// The web server's gate, on the real app over real HTTP: every state-changing
// route refuses what a page of another site could send (another origin, a
// form, text/plain); a method no route offers is 405 on routes and pages;
// pages take no body and never read one; a NUL in a sound's name is refused
// in words; and someone not signed in learns nothing of the deployment's
// addresses from a page that sends them to the sign-in.
import { request } from "node:http";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { silentWav } from "../support/audio";
import { apiClient, signIn } from "../support/http";
import { apiRouteFiles } from "../support/routes";

let app: RunningApp;
let cookie = "";
let studyId = "";
let soundsBefore = 0;
const sounds = async () => (await apiClient(app.url, cookie).audio.list.query({ studyId })).length;

beforeAll(async () => {
  app = await startApp();
  cookie = await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD);
  studyId = (await apiClient(app.url, cookie).studies.mine.query())[0]!.id;
  soundsBefore = await sounds();
}, 300_000);
afterAll(() => app?.stop());

/** Each route's path with its parameters filled in, and the methods it offers that change something. */
const CHANGES = ["POST", "PUT", "PATCH", "DELETE"];
const PARAMS: Record<string, string> = { "...all": "sign-out", trpc: "studies.create", index: "0" };
const changing: Array<[string, string]> = [];
for (const route of apiRouteFiles()) {
  const handlers = (await import(`../../src/app/api/${route}/route`)) as Record<string, unknown>;
  for (const method of CHANGES) if (typeof handlers[method] === "function") changing.push([route, method]);
}
const pathOf = (route: string) =>
  `/api/${route.replace(/\[([.\w]+)\]/g, (_, name: string) => (name === "studyId" && studyId ? studyId : (PARAMS[name] ?? crypto.randomUUID())))}`;

/**
 * A request as Node sends it (fetch cannot send TRACE). With `declared`, the
 * headers announce a body of that length and none of it is sent until the
 * server has answered: a server that waits for the body never answers.
 */
function raw(
  method: string,
  path: string,
  declared?: number,
): Promise<{ status: number; headers: Record<string, unknown>; text: string }> {
  return new Promise((resolve, reject) => {
    const req = request(`${app.url}${path}`, {
      method,
      headers: declared === undefined ? {} : { "content-length": String(declared) },
    });
    req.on("response", (res) => {
      let text = "";
      res.setEncoding("utf8");
      res.on("data", (d) => (text += d));
      res.on("end", () => {
        resolve({ status: res.statusCode!, headers: res.headers, text });
        req.destroy();
      });
    });
    req.on("error", reject);
    if (declared === undefined) req.end();
    else req.flushHeaders();
  });
}

describe("the web server's gate", () => {
  it("finds the routes that change something", () => {
    expect(changing).toEqual(
      expect.arrayContaining([
        ["studies/[studyId]/audio", "POST"],
        ["recordings/[recordingId]/chunks/[index]", "PUT"],
        ["auth/[...all]", "POST"],
        ["trpc/[trpc]", "POST"],
      ]),
    );
  });

  const ATTACKS: Array<[string, Record<string, string>, number]> = [
    ["from another origin", { "content-type": "audio/wav", origin: "http://lab.example:3000" }, 403],
    ["as text/plain", { "content-type": "text/plain;charset=UTF-8" }, 415],
    ["as a form", { "content-type": "application/x-www-form-urlencoded" }, 415],
  ];
  it.each(
    changing.flatMap(([route, method]) =>
      ATTACKS.map(([attack, headers, status]) => [route, method, attack, headers, status] as const),
    ),
  )("%s %s %s, with a signed-in cookie: refused", async (route, method, _, headers, status) => {
    const res = await fetch(`${app.url}${pathOf(route)}?name=planted.wav`, {
      method,
      // An own-origin attack names the app's own address, known only once it runs.
      headers: { ...headers, ...(headers.origin === "" ? { origin: app.url } : {}), cookie },
      body: silentWav(20),
    });
    expect(res.status, await res.clone().text()).toBe(status);
    expect(await res.text()).toMatch(/^A change sent (from another site's page|as [\w/-]+) is refused/);
  });

  it("stored none of those sounds, and takes one from the app's own page", async () => {
    expect(await sounds()).toBe(soundsBefore);
    const res = await fetch(`${app.url}/api/studies/${studyId}/audio?name=own.wav`, {
      method: "POST",
      headers: { "content-type": "audio/wav", origin: app.url, cookie },
      body: silentWav(20),
    });
    expect(res.status, await res.clone().text()).toBe(201);
    expect(await sounds()).toBe(soundsBefore + 1);
  });

  it("refuses a NUL in a sound's name in words", async () => {
    const res = await fetch(`${app.url}/api/studies/${studyId}/audio?name=a%00b.wav`, {
      method: "POST",
      headers: { "content-type": "audio/wav", origin: app.url, cookie },
      body: silentWav(20),
    });
    expect(res.status).toBe(400);
    expect(await res.text()).toBe("Please correct: name: must not contain the NUL character (\\0)");
  });

  it.each([
    ...["/", "/sign-in", "/robot", `/studies/${crypto.randomUUID()}`].map((p) => [p]),
    ...apiRouteFiles().map((route) => [pathOf(route)]),
  ])("answers TRACE %s with 405", async (path) => {
    const res = await raw("TRACE", path);
    expect(res.status).toBe(405);
    expect(res.text).toMatch(/does not take TRACE requests/);
  });

  it("refuses a page read that carries a body (1 GB declared) without reading it", async () => {
    const res = await raw("GET", "/sign-in", 1024 * 1024 * 1024);
    expect(res.status).toBe(413);
    expect(res.text).toBe("A page takes no request body.");
    // The connection ends with the answer: the body is never read.
    expect(res.headers.connection).toBe("close");
  });

  it("tells someone not signed in nothing of the deployment's addresses", async () => {
    const res = await fetch(`${app.url}/robot`, { redirect: "manual" });
    expect(res.status).toBe(307);
    expect(res.headers.get("location")).toMatch(/\/sign-in$/);
    const everything = JSON.stringify([...res.headers]) + (await res.text());
    for (const address of [app.simulatorUrl, app.runtimeUrl]) expect(everything).not.toContain(new URL(address).host);
  });
});
