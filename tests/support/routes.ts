// Route handlers called in-process, as Next.js calls them. They take the
// server's shared parts from the environment (server() in
// src/server/context.ts), so this points the environment at a fresh database
// and a throwaway media folder first; every test file runs in its own process.
import { readdirSync, statSync } from "node:fs";
import { join, relative } from "node:path";
import { freshDatabase } from "./db";
import { scratchFolder } from "./scratch";
import { API_BASE, ENDPOINTS } from "../../src/core/analysis/api";
import type { Database } from "../../src/store/client";
import { buildFixture, TEST_SECRET, type Caller } from "../api/fixture";

export const ORIGIN = "http://localhost:3000";

/** With `database`, on that one (a PostgreSQL of the test's own); else on a fresh database of the suite's server. */
export async function routeServer(database?: { url: string; db: Database; close: () => Promise<void> }) {
  database ??= await freshDatabase();
  Object.assign(process.env, {
    DATABASE_URL: database.url,
    BETTER_AUTH_SECRET: TEST_SECRET,
    BETTER_AUTH_URL: ORIGIN,
    HRI_MEDIA_DIR: scratchFolder("route-media-"),
    HRI_MEDIA_S3_URL: "",
  });
  const { server, contextFromHeaders } = await import("../../src/server/context");
  const { appRouter } = await import("../../src/server/api/root");
  const auth = await import("../../src/app/api/auth/[...all]/route");
  const f = await buildFixture(database.db);

  /** Signs a fixture person in through the auth route; the cookie header of their session. */
  async function signIn(caller: Exclude<Caller, "anonymous">): Promise<Headers> {
    const res = await auth.POST(
      new Request(`${ORIGIN}/api/auth/sign-in/email`, {
        method: "POST",
        headers: { "content-type": "application/json", origin: ORIGIN },
        body: JSON.stringify({ email: f.people[caller].email, password: "password-123" }),
      }),
    );
    if (!res.ok) throw new Error(`Signing in as ${caller} failed: ${res.status} ${await res.text()}`);
    const cookie = res.headers
      .getSetCookie()
      .map((c) => c.split(";")[0])
      .join("; ");
    return new Headers({ cookie, origin: ORIGIN });
  }

  /** The API as a signed-in person calls it from a route, with the server's own media store. */
  async function apiAs(headers: Headers) {
    return appRouter.createCaller(await contextFromHeaders(headers));
  }

  return { ...database, f, server: server(), signIn, apiAs };
}

/** A body that never ends, counting how many bytes the reader pulled. */
export function endlessBody(piece = 64 * 1024) {
  const counted = { pulled: 0, cancelled: false };
  const body = new ReadableStream<Uint8Array>(
    {
      pull(controller) {
        counted.pulled += piece;
        controller.enqueue(new Uint8Array(piece).fill(120));
      },
      cancel() {
        counted.cancelled = true;
      },
    },
    { highWaterMark: 0 },
  );
  return { body, counted };
}

const API = join(import.meta.dirname, "..", "..", "src", "app", "api");

/** Every route under src/app/api, as its folder below it ("studies/[studyId]/audio"). */
export function apiRouteFiles(dir = API): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return apiRouteFiles(path);
    return name === "route.ts" ? [relative(API, dir)] : [];
  });
}

/** A request to the analysis API (/api/v1) answered by its route handler, the path's ids given as Next.js gives them. */
export async function analysisRoute(request: Request): Promise<Response> {
  const route = new URL(request.url).pathname.slice(API_BASE.length);
  const declared = Object.values(ENDPOINTS).find((e) =>
    new RegExp(`^${e.path.replace(/\{\w+\}/g, "[^/]+")}$`).test(route),
  );
  if (!declared) return Response.json({ error: `No analysis API route at ${route}` }, { status: 404 });
  const values = route.split("/");
  const params = Object.fromEntries(
    declared.path
      .split("/")
      .map((part, i) => [part, values[i]!] as const)
      .filter(([part]) => part.startsWith("{"))
      .map(([part, value]) => [part.slice(1, -1), value]),
  );
  const file = declared.path.replace(/\{(\w+)\}/g, "[$1]");
  const handlers = (await import(/* @vite-ignore */ `../../src/app/api/v1${file}/route`)) as {
    GET: (req: Request, ctx: { params: Promise<Record<string, string>> }) => Promise<Response>;
  };
  return handlers.GET(request, { params: Promise.resolve(params) });
}
