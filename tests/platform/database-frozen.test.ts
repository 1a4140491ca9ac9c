// Fail fast without the database: with the PostgreSQL server frozen (every
// process SIGSTOPped, as a hung server would be), the API and a route answer
// 503 with a plain sentence instead of holding the request for good, and once
// it thaws they work again. The server is a PostgreSQL of the test's own, so
// freezing it stops no other test; the handlers are the real ones, called
// in-process as Next.js calls them.
import { rm } from "node:fs/promises";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { createDatabase } from "../../src/store/client";
import { startEmbeddedPostgres, type EmbeddedDatabase } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { signalDatabase } from "../support/frozen-postgres";
import { ORIGIN, routeServer } from "../support/routes";
import { scratchFolder } from "../support/scratch";

let dataDir = "";
let pg: EmbeddedDatabase;
let s: Awaited<ReturnType<typeof routeServer>>;
let cookie: Headers;
let studyId = "";

beforeAll(async () => {
  dataDir = scratchFolder("frozen-pg-");
  pg = await startEmbeddedPostgres({ dataDir });
  await migrateDatabase(pg.url);
  s = await routeServer({ url: pg.url, ...createDatabase(pg.url) });
  cookie = await s.signIn("owner");
  studyId = (await s.f.newStudy()).id;
}, 120_000);

afterAll(async () => {
  await signalDatabase(dataDir, "SIGCONT").catch(() => {});
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
