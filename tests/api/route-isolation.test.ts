// The REST routes (downloads, recording parts and media), generated from the
// route files themselves: every route and method × every kind of caller of
// study A, called (a) with A's ids, (b) with study B's, and (c) with B's ids in
// the path and A's smuggled beside them in the query. B's answer never comes
// back, and nothing of B is written.
import { afterAll, describe, expect, it } from "vitest";
import { newPerson, type Caller } from "./fixture";
import { apiRouteFiles, ORIGIN, routeServer } from "../support/routes";
import { appRouter } from "../../src/server/api/root";
import { contextFromHeaders } from "../../src/server/context";
import { addAudio } from "../../src/server/media/audio";
import { silentWav } from "../support/audio";

const s = await routeServer();
afterAll(s.close);

/**
 * auth and trpc are the doors the other tests walk through; the analysis API's
 * two routes that take no id (its study list and its description) are
 * tests/api/analysis-api.test.ts's; every other route is here.
 */
const OWN_TESTS = new Set(["auth/[...all]", "trpc/[trpc]", "v1/studies", "v1/openapi.json"]);

const routes = apiRouteFiles().filter((r) => !OWN_TESTS.has(r));

/** A study with a finished recording and a recording still taking parts, built by `api`. */
async function studyWithRows(api: Awaited<ReturnType<typeof s.apiAs>>, studyId: string, code: string) {
  await api.studies.update({ studyId, status: "active" });
  const e = await api.experiments.create({ studyId, name: `Experiment ${code}`, robotId: "nao6-ros2" });
  await api.experiments.saveDesign({
    experimentId: e.id,
    baseRevision: 0,
    steps: [{ name: "S", actions: [{ type: "say", parameters: { text: `secret of ${code}` } }] }],
  });
  const version = await api.versions.publish({ experimentId: e.id });
  const p = await api.participants.create({ studyId, code, consentStatus: "given", consentDate: new Date() });
  const trial = await api.trials.create({ versionId: version.id, participantId: p.id });
  const finished = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
  await s.server.media.storage.put(
    `recordings/${finished.recordingId}/chunk-000000`,
    new TextEncoder().encode(`video of ${code}`),
    "video/mp4",
  );
  await api.recordings.finish({ recordingId: finished.recordingId, durationMs: 1000 });
  const open = await api.recordings.start({ trialId: trial.id, kind: "video", mimeType: "video/mp4" });
  const audio = await addAudio(s.db, s.server.media.storage, {
    studyId,
    userId: (await api.account.me()).id,
    name: `sound of ${code}.wav`,
    bytes: silentWav(20),
  });
  if (!audio.ok) throw new Error(audio.reason);
  return {
    studyId,
    trialId: trial.id,
    recordingId: finished.recordingId,
    openRecordingId: open.recordingId,
    audioFileId: audio.audio.id,
  };
}

const ownerHeaders = await s.signIn("owner");
const a = await studyWithRows(await s.apiAs(ownerHeaders), (await s.f.newStudy()).id, "A-1");
const victim = await newPerson(s.db, "victim");
// B's owner works through the same server (its media store included) as A's.
const victimApi = appRouter.createCaller({ ...(await contextFromHeaders(new Headers())), user: victim });
const b = await studyWithRows(victimApi, (await victimApi.studies.create({ title: "Victim" })).id, "B-1");
const storedOfB = async () =>
  JSON.stringify([
    await s.server.media.storage.list(`recordings/${b.openRecordingId}/`),
    await s.server.media.storage.list(`audio/${b.studyId}/`),
  ]);
const before = await storedOfB();

type Ids = typeof a;
/** The value of a path parameter: ids from the study given; a part number is just a number. */
function param(name: string, ids: Ids, method: string): string {
  if (name === "index") return "0";
  // Parts go to a recording still taking them; media comes from a finished one.
  if (name === "recordingId") return method === "PUT" ? ids.openRecordingId : ids.recordingId;
  const value = (ids as Record<string, string>)[name];
  if (!value) throw new Error(`route parameter [${name}] has no test ids: add it to studyWithRows`);
  return value;
}

async function call(route: string, method: string, ids: Ids, who: Headers | null, query = "") {
  const handlers = (await import(`../../src/app/api/${route}/route`)) as Record<
    string,
    (req: Request, ctx: { params: Promise<Record<string, string>> }) => Promise<Response>
  >;
  const params = Object.fromEntries(
    [...route.matchAll(/\[(\w+)\]/g)].map(([, name]) => [name!, param(name!, ids, method)]),
  );
  const path = route.replace(/\[(\w+)\]/g, (_, name: string) => params[name]!);
  // The analysis API (v1) reads a personal access token, and nothing else, where the others read the session.
  const credentials: Record<string, string> = route.startsWith("v1/")
    ? who && bearer.has(who)
      ? { authorization: `Bearer ${bearer.get(who)}` }
      : {}
    : who
      ? { cookie: who.get("cookie")! }
      : {};
  const init: RequestInit = { method, headers: { ...credentials, "content-type": "video/mp4" } };
  // A sound where the route takes one (it refuses anything else before it could matter), a part elsewhere.
  if (method === "PUT" || method === "POST")
    init.body = route.endsWith("/audio") ? silentWav(20) : new TextEncoder().encode("smuggled part");
  return handlers[method]!(new Request(`${ORIGIN}/api/${path}${query}`, init), { params: Promise.resolve(params) });
}

const METHODS = ["GET", "PUT", "POST", "DELETE", "PATCH"];
const cases: Array<[string, string]> = [];
for (const route of routes) {
  const handlers = (await import(`../../src/app/api/${route}/route`)) as Record<string, unknown>;
  for (const method of METHODS) if (typeof handlers[method] === "function") cases.push([route, method]);
}
const CALLERS: Caller[] = ["owner", "researcher", "wizard", "observer", "outsider", "admin", "anonymous"];
const signedIn: Partial<Record<Caller, Headers>> = { owner: ownerHeaders };
for (const caller of CALLERS)
  if (caller !== "anonymous" && !signedIn[caller]) signedIn[caller] = await s.signIn(caller);
/** Each caller who may read study A's data holds an access token for A, the others none. */
const bearer = new Map<Headers, string>();
for (const caller of ["owner", "researcher", "observer"] as const) {
  const made = await (await s.apiAs(signedIn[caller]!)).tokens.create({
    name: "route isolation",
    studyIds: [a.studyId],
    expiresInDays: 1,
  });
  bearer.set(signedIn[caller]!, made.secret);
}

describe("REST routes keep studies apart", () => {
  it("finds the routes", () => {
    expect(cases.map(([r, m]) => `${m} ${r}`).sort()).toEqual(
      expect.arrayContaining([
        "GET recordings/[recordingId]/media",
        "PUT recordings/[recordingId]/chunks/[index]",
        "GET trials/[trialId]/export",
        "GET trials/[trialId]/events",
        "GET audio/[audioFileId]",
        "POST studies/[studyId]/audio",
      ]),
    );
  });

  it.each(cases)("%s %s works for study A's owner with A's ids", async (route, method) => {
    const res = await call(route, method, a, ownerHeaders);
    expect(res.status, await res.clone().text()).toBeLessThan(300);
  });

  const attacks = cases.flatMap(([route, method]) => CALLERS.map((caller) => [route, method, caller] as const));
  it.each(attacks)(
    "%s %s by %s of study A: refused with study B's ids, alone or beside A's",
    async (route, method, caller) => {
      const smuggled = `?studyId=${a.studyId}&trialId=${a.trialId}&recordingId=${a.recordingId}`;
      for (const query of ["", smuggled]) {
        const res = await call(route, method, b, signedIn[caller] ?? null, query);
        const text = await res.text();
        expect(
          [401, 403, 404],
          `${caller} with B's ids${query ? " and A's in the query" : ""}: ${res.status} ${text}`,
        ).toContain(res.status);
        expect(text).not.toMatch(/B-1|Victim/);
      }
    },
  );

  it("stored no part in study B's recording", async () => {
    expect(await storedOfB()).toBe(before);
  });
});
