// Fail fast without the database: with the PostgreSQL server frozen (every
// process SIGSTOPped, as a hung server would be), the API, a route and a page
// answer 503 with a plain sentence instead of holding the request for good,
// also when the database goes away partway through a request, and once it
// thaws they work again. The server is a PostgreSQL of the test's own, so
// freezing it stops no other test; the handlers are the real ones, called
// in-process as Next.js calls them, and the page is the real app's.
import { rm } from "node:fs/promises";
import { afterAll, afterEach, beforeAll, describe, expect, it } from "vitest";
import { createDatabase } from "../../src/store/client";
import { startEmbeddedPostgres, type EmbeddedDatabase } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { signalDatabase } from "../support/frozen-postgres";
import { signIn } from "../support/http";
import { ORIGIN, routeServer } from "../support/routes";
import { scratchFolder } from "../support/scratch";

let dataDir = "";
let pg: EmbeddedDatabase;
let s: Awaited<ReturnType<typeof routeServer>>;
let cookie: Headers;
let studyId = "";
let app: RunningApp;
/** The test's own connections to the database, apart from the app's. */
let database: ReturnType<typeof createDatabase>;

beforeAll(async () => {
  // First, from the environment as it is: the route server below points it at its own database.
  app = await startApp();
  dataDir = scratchFolder("frozen-pg-");
  pg = await startEmbeddedPostgres({ dataDir });
  await migrateDatabase(pg.url);
  database = createDatabase(pg.url);
  s = await routeServer({ url: pg.url, ...database });
  cookie = await s.signIn("owner");
  studyId = (await s.f.newStudy()).id;
}, 600_000);

afterAll(async () => {
  await signalDatabase(dataDir, "SIGCONT").catch(() => {});
  if (app) await signalDatabase(app.dataDir, "SIGCONT").catch(() => {});
  await app?.stop();
  await s?.close();
  await pg?.stop();
  await rm(dataDir, { recursive: true, force: true });
});

const trpc = await import("../../src/app/api/trpc/[trpc]/route");
const questionnaires = await import("../../src/app/api/studies/[studyId]/questionnaires/route");

/** The answer, or a failure once a generous minute has passed: the request hung. */
async function answer(call: () => Promise<Response>): Promise<{ status: number; text: string }> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const hung = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error("The request was not answered within a minute: it hangs.")), 60_000);
  });
  const res = await Promise.race([call(), hung]).finally(() => clearTimeout(timer));
  return { status: res.status, text: await res.text() };
}

const askApi = () => answer(() => trpc.GET(new Request(`${ORIGIN}/api/trpc/studies.mine`, { headers: cookie })));
const askRoute = () =>
  answer(() =>
    questionnaires.GET(new Request(`${ORIGIN}/api/studies/${studyId}/questionnaires`, { headers: cookie }), {
      params: Promise.resolve({ studyId }),
    }),
  );

describe("with the database frozen", () => {
  it("the API and a route say the database is unavailable (503), and work again once it is back", {
    timeout: 180_000,
  }, async () => {
    expect((await askApi()).status).toBe(200);
    expect((await askRoute()).status).toBe(200);

    await signalDatabase(dataDir, "SIGSTOP");
    const api = await askApi();
    expect(api.status).toBe(503);
    expect(JSON.parse(api.text).error.message).toBe("The database is unavailable; try again in a moment.");
    const route = await askRoute();
    expect(route).toEqual({ status: 503, text: "The database is unavailable; try again in a moment." });

    await signalDatabase(dataDir, "SIGCONT");
    expect((await askApi()).status).toBe(200);
    expect((await askRoute()).status).toBe(200);
  });
});

/** Lets go of the lock the last test took: at once, or after it if it failed first. */
let letGo = async () => {};

/**
 * Holds the table of studies locked until `release`: a request's query of it
 * waits, after its session was looked up, until the test does something to
 * the database. Resolves once that query is waiting.
 */
async function queryHeldBy() {
  let release = () => {};
  const released = new Promise<void>((ok) => (release = ok));
  const held = database.sql.begin(async (tx) => {
    await tx`lock table studies in access exclusive mode`;
    await released;
  });
  // The lock is taken before the request starts.
  await expect
    .poll(() =>
      database.sql`select 1 from pg_locks where relation = 'studies'::regclass and granted`.then((r) => r.length),
    )
    .toBe(1);
  const request = askApi();
  const waiting = () =>
    database.sql`select pid from pg_stat_activity where wait_event_type = 'Lock' and datname = current_database()`.then(
      (rows) => rows.map((r) => r.pid as number),
    );
  await expect.poll(() => waiting().then((pids) => pids.length)).toBe(1);
  letGo = () => {
    release();
    return held;
  };
  return { request, waiting, release: letGo };
}

describe("a database that goes away during a procedure", () => {
  afterEach(async () => {
    await signalDatabase(dataDir, "SIGCONT");
    await letGo();
  });

  it("a slow procedure whose database answers is left to finish", { timeout: 180_000 }, async () => {
    const { request, release } = await queryHeldBy();
    // Past the moment the procedure's watch asks the database whether it still answers.
    await new Promise((r) => setTimeout(r, 6000));
    await release();
    expect((await request).status).toBe(200);
  });

  it("slow procedures holding every connection of the pool are left to finish", { timeout: 180_000 }, async () => {
    const { request, waiting, release } = await queryHeldBy();
    // The rest of the web app's pool (createDatabase's ten), each request waiting on the same lock.
    const others = Array.from({ length: 9 }, () => askApi());
    await expect.poll(() => waiting().then((pids) => pids.length), { timeout: 30_000 }).toBe(10);
    // Past the watch's question: asked through a pool with no connection free, it went unanswered (a 503).
    await new Promise((r) => setTimeout(r, 6000));
    await release();
    expect((await Promise.all([request, ...others])).map((a) => a.status)).toEqual(Array(10).fill(200));
  });

  it("a connection dropped under a procedure answers 503 at once, not 500", { timeout: 180_000 }, async () => {
    const { request, waiting, release } = await queryHeldBy();
    const [pid] = await waiting();
    await database.sql`select pg_terminate_backend(${pid!})`;
    const api = await request;
    expect(api.status).toBe(503);
    expect(JSON.parse(api.text).error.message).toBe("The database is unavailable; try again in a moment.");
    await release();
    expect((await askApi()).status).toBe(200);
  });

  it("a database frozen after the session was looked up answers 503", { timeout: 180_000 }, async () => {
    const { request, release } = await queryHeldBy();
    await signalDatabase(dataDir, "SIGSTOP");
    const api = await request;
    expect(api.status).toBe(503);
    expect(JSON.parse(api.text).error.message).toBe("The database is unavailable; try again in a moment.");

    await signalDatabase(dataDir, "SIGCONT");
    await release();
    expect((await askApi()).status).toBe(200);
  });
});

describe("a page of the real app, with its database frozen", () => {
  it("says the database is unavailable (503) in a plain page, and works again once it is back", {
    timeout: 180_000,
  }, async () => {
    const cookie = await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD);
    const page = () => answer(() => fetch(`${app.url}/studies`, { headers: { cookie }, redirect: "manual" }));
    expect((await page()).status).toBe(200);

    await signalDatabase(app.dataDir, "SIGSTOP");
    const frozen = await page();
    expect(frozen.status).toBe(503);
    expect(frozen.text).toContain("The database is unavailable; try again in a moment.");

    await signalDatabase(app.dataDir, "SIGCONT");
    expect((await page()).status).toBe(200);
    // The failed session lookup is logged without its query's parameters: the session's token is not in the log.
    const token = decodeURIComponent(/session_token=([^;]+)/.exec(cookie)![1]!).split(".")[0]!;
    expect(token.length).toBeGreaterThan(10);
    expect(app.output()).not.toContain(token);
  });
});
