// The analysis API (/api/v1) through its route handlers, with real personal
// access tokens against a real database: what a token reaches (its studies,
// as its owner is now), what it is refused (another study's ids, alone or
// mixed; an expired, revoked or unknown token; a session cookie), the formats,
// and the audit log's record of tokens.
import Ajv2020 from "ajv/dist/2020";
import { eq } from "drizzle-orm";
import { afterAll, describe, expect, it, vi } from "vitest";
import { hashTokenSecret } from "../../src/core/access/token-secret";
import { API_BASE, ENDPOINTS, STUDY_COLUMNS, TRIAL_COLUMNS } from "../../src/core/analysis/api";
import { EVENT_COLUMNS } from "../../src/core/analysis/exports";
import { openApiDocument } from "../../src/core/analysis/openapi";
import { CODE_COLUMNS } from "../../src/core/coding/export";
import { ANSWER_COLUMNS } from "../../src/core/questionnaires/export";
import { codingRows } from "../support/coding";
import { accessTokens, annotations, auditLog, trialSamples, trials } from "../../src/store/schema";
import { appendEvents } from "../../src/store/event-store";
import { parseCsv } from "../support/csv";
import { analysisRoute, ORIGIN, routeServer } from "../support/routes";
import { newPerson } from "./fixture";
import { appRouter } from "../../src/server/api/root";
import { contextFromToken } from "../../src/server/tokens/context";

const s = await routeServer();
afterAll(s.close);
const ownerCookie = await s.signIn("owner");
const owner = await s.apiAs(ownerCookie);

/** A study with one finished-looking trial: events, a robot sample, an annotation. */
async function studyWithTrial(title: string, code: string) {
  const study = await s.f.newStudy(title);
  const e = await owner.experiments.create({ studyId: study.id, name: `Greeting ${code}`, robotId: "nao6-ros2" });
  await owner.experiments.saveDesign({
    experimentId: e.id,
    baseRevision: 0,
    steps: [{ name: "Welcome", actions: [{ type: "say", parameters: { text: `Hello ${code}` } }] }],
  });
  const version = await owner.versions.publish({ experimentId: e.id });
  const p = await owner.participants.create({
    studyId: study.id,
    code,
    consentStatus: "given",
    consentDate: new Date(),
  });
  const trial = await owner.trials.create({ versionId: version.id, participantId: p.id });
  await appendEvents(
    s.db,
    { id: trial.id, lastSeq: 0, t0: null },
    [{ type: "trial.started" }, { type: "note.added", text: `note of ${code}` }],
    s.f.people.owner.id,
  );
  await s.db.insert(trialSamples).values({ trialId: trial.id, topic: "/joint_states", relMs: 20, data: { code } });
  await s.db
    .insert(annotations)
    .values({ trialId: trial.id, relMs: 10, label: `look ${code}`, authorId: s.f.people.observer.id });
  await codingRows(owner, study.id, trial.id);
  return { studyId: study.id, trialId: trial.id, participantId: p.id };
}

const a = await studyWithTrial("Study A", "A-1");
const b = await studyWithTrial("Study B", "B-1");
const tokenA = (await owner.tokens.create({ name: "A only", studyIds: [a.studyId], expiresInDays: 30 })).secret;

/** Calls a v1 route as Next.js would. */
const get = (path: string, headers: Record<string, string> = {}) =>
  analysisRoute(new Request(`${ORIGIN}${API_BASE}${path}`, { headers }));
const as = (secret: string, extra: Record<string, string> = {}) => ({ authorization: `Bearer ${secret}`, ...extra });
const csvOf = async (res: Response) => parseCsv(await res.text());

describe("what a token reads", () => {
  it("lists only the token's studies", async () => {
    const [header, ...rows] = await csvOf(await get("/studies", as(tokenA)));
    expect(header).toEqual([...STUDY_COLUMNS]);
    expect(rows).toEqual([[a.studyId, "Study A", "active", "owner", "false"]]);
  });

  it("returns the study's trials, events, samples, answers, annotations and codes as tidy CSV", async () => {
    const [trialsHeader, ...trials] = await csvOf(await get(`/studies/${a.studyId}/trials`, as(tokenA)));
    expect(trialsHeader).toEqual([...TRIAL_COLUMNS]);
    expect(trials.map((t) => [t[0], t[1], t[3]])).toEqual([[a.trialId, "Greeting A-1", "A-1"]]);
    const [eventsHeader, ...events] = await csvOf(await get(`/studies/${a.studyId}/events`, as(tokenA)));
    expect(eventsHeader).toEqual([...EVENT_COLUMNS]);
    expect(events.map((e) => [e[0], e[3], e[4]])).toEqual([
      [a.trialId, "1", "trial.started"],
      [a.trialId, "2", "note.added"],
    ]);
    const [, sample] = await csvOf(await get(`/studies/${a.studyId}/samples`, as(tokenA)));
    expect(sample).toEqual([a.trialId, "/joint_states", "20", '{"code":"A-1"}']);
    const [, note] = await csvOf(await get(`/studies/${a.studyId}/annotations`, as(tokenA)));
    expect(note).toEqual([a.trialId, "10", "look A-1", "", "observer"]);
    const [codesHeader, ...codes] = await csvOf(await get(`/studies/${a.studyId}/codes`, as(tokenA)));
    expect(codesHeader).toEqual([...CODE_COLUMNS]);
    expect(codes).toEqual([
      [a.trialId, "owner", "Wizard interventions", "1", "Intervention type", "Hint", "point", "1500", "", ""],
    ]);
    const answers = await get(`/studies/${a.studyId}/answers`, as(tokenA));
    expect([answers.status, (await csvOf(answers))[0]]).toEqual([200, [...ANSWER_COLUMNS]]);
    const [, ...one] = await csvOf(await get(`/trials/${a.trialId}/events`, as(tokenA)));
    expect(one).toEqual(events);
  });

  it("gives each table's JSON in the types its description declares", async () => {
    // A time is ISO 8601 in UTC, as every export writes it.
    const utc = (text: string) => !Number.isNaN(Date.parse(text)) && text.endsWith("Z");
    const ajv = new Ajv2020({ strict: false, formats: { "date-time": utc } });
    const described = openApiDocument().paths as Record<string, { get: { responses: Record<string, unknown> } }>;
    for (const [name, endpoint] of Object.entries(ENDPOINTS)) {
      const path = endpoint.path.replace("{studyId}", a.studyId).replace("{trialId}", a.trialId);
      const records = (await (await get(`${path}?format=json`, as(tokenA))).json()) as unknown[];
      const { schema } = (
        described[`${API_BASE}${endpoint.path}`]!.get.responses["200"] as {
          content: { "application/json": { schema: object } };
        }
      ).content["application/json"];
      const valid = ajv.validate(schema, records);
      expect([name, records.length > 0, valid ? [] : ajv.errors]).toEqual([name, name !== "answers", []]);
    }
  });

  it("switches to JSON records with ?format=json or Accept: application/json; refuses an unknown format", async () => {
    const viaQuery = await get(`/studies/${a.studyId}/trials?format=json`, as(tokenA));
    expect(viaQuery.headers.get("content-type")).toBe("application/json");
    const records = (await viaQuery.json()) as Array<Record<string, unknown>>;
    expect(records).toEqual([expect.objectContaining({ trial_id: a.trialId, participant: "A-1", ended_at: null })]);
    const viaAccept = await get(`/studies/${a.studyId}/trials`, as(tokenA, { accept: "application/json" }));
    expect(await viaAccept.json()).toEqual(records);
    const csv = await get(`/studies/${a.studyId}/trials?format=csv`, as(tokenA, { accept: "application/json" }));
    expect(csv.headers.get("content-type")).toBe("text/csv; charset=utf-8");
    const wrong = await get(`/studies/${a.studyId}/trials?format=xlsx`, as(tokenA));
    expect([wrong.status, await wrong.json()]).toEqual([
      400,
      { error: "Please correct: format: must be csv or json (not “xlsx”)" },
    ]);
  });
});

describe("what a token is refused", () => {
  const NOT_FOUND = /^No such (study|trial), or it belongs to a study you are not a member of\.$/;

  it.each(Object.keys(ENDPOINTS).filter((n) => n !== "studies"))(
    "%s: another study's id, one of the owner's own, reads like an unknown one (404)",
    async (name) => {
      const path = ENDPOINTS[name as keyof typeof ENDPOINTS].path;
      for (const ids of [b, { studyId: "no-such-study", trialId: "no-such-trial" }]) {
        const res = await get(path.replace("{studyId}", ids.studyId).replace("{trialId}", ids.trialId), as(tokenA));
        const body = await res.text();
        expect([res.status, JSON.parse(body).error]).toEqual([404, expect.stringMatching(NOT_FOUND)]);
        expect(body).not.toMatch(/B-1|Study B/);
      }
    },
  );

  it("refuses mixed ids: B's trial asked for beside A's study in the query", async () => {
    const res = await get(`/trials/${b.trialId}/events?studyId=${a.studyId}&trialId=${a.trialId}`, as(tokenA));
    expect(res.status).toBe(404);
    expect(await res.text()).not.toMatch(/B-1/);
  });

  it("answers 401 in plain JSON without a token, with a session cookie alone, or with an unknown token", async () => {
    const path = `/studies/${a.studyId}/events`;
    for (const headers of [
      {},
      { cookie: ownerCookie.get("cookie")! },
      as("hri_not-a-real-token"),
      as("not ours"),
    ] as Array<Record<string, string>>) {
      const res = await get(path, headers);
      expect(res.status).toBe(401);
      expect(res.headers.get("www-authenticate")).toMatch(/^Bearer/);
      expect((await res.json()).error).toMatch(/access token/);
    }
  });

  it("stops working when it expires or is revoked", async () => {
    const expiring = await owner.tokens.create({ name: "Short", studyIds: [a.studyId], expiresInDays: 1 });
    expect((await get("/studies", as(expiring.secret))).status).toBe(200);
    await s.db
      .update(accessTokens)
      .set({ expiresAt: new Date(Date.now() - 1000) })
      .where(eq(accessTokens.id, expiring.id));
    const expired = await get("/studies", as(expiring.secret));
    expect([expired.status, (await expired.json()).error]).toEqual([401, expect.stringMatching(/has expired/)]);

    const revoking = await owner.tokens.create({ name: "Revoked", studyIds: [a.studyId], expiresInDays: 1 });
    await owner.tokens.revoke({ tokenId: revoking.id });
    const revoked = await get(`/studies/${a.studyId}/trials`, as(revoking.secret));
    expect([revoked.status, (await revoked.json()).error]).toEqual([401, expect.stringMatching(/was revoked/)]);
    expect((await owner.tokens.list()).find((t) => t.id === revoking.id)?.state).toBe("revoked");
  });

  it("never reaches more than its owner now has: a removed member's token loses the study, a disabled account's stops", async () => {
    const researcher = await s.apiAs(await s.signIn("researcher"));
    const token = await researcher.tokens.create({ name: "Mine", studyIds: [a.studyId, b.studyId], expiresInDays: 5 });
    expect((await csvOf(await get("/studies", as(token.secret)))).length).toBe(3);
    await owner.members.remove({ studyId: b.studyId, userId: s.f.people.researcher.id });
    expect((await csvOf(await get("/studies", as(token.secret)))).map((r) => r[0])).toEqual(["study_id", a.studyId]);
    expect((await get(`/studies/${b.studyId}/trials`, as(token.secret))).status).toBe(404);
    expect((await get(`/trials/${b.trialId}/events`, as(token.secret))).status).toBe(404);
    expect((await get(`/studies/${a.studyId}/trials`, as(token.secret))).status).toBe(200);

    await s.f.api("admin").admin.users.setDisabled({ userId: s.f.people.researcher.id, disabled: true });
    const disabled = await get(`/studies/${a.studyId}/trials`, as(token.secret));
    expect([disabled.status, (await disabled.json()).error]).toEqual([401, expect.stringMatching(/disabled/)]);
    await s.f.api("admin").admin.users.setDisabled({ userId: s.f.people.researcher.id, disabled: false });
  });

  it("keeps the owner's blinds: results hidden until the study is complete are hidden from the token too (403)", async () => {
    const blinded = await studyWithTrial("Blinded study", "C-1");
    const observer = await s.apiAs(await s.signIn("observer"));
    const token = await observer.tokens.create({ name: "Blind", studyIds: [blinded.studyId], expiresInDays: 5 });
    await owner.studies.update({
      studyId: blinded.studyId,
      settings: { blinding: { conditionsFromWizards: false, resultsUntilComplete: true } },
    });
    const refused = await get(`/studies/${blinded.studyId}/events`, as(token.secret));
    expect([refused.status, (await refused.json()).error]).toEqual([
      403,
      "This study hides results until it is marked completed (blinding).",
    ]);
    expect((await csvOf(await get("/studies", as(token.secret))))[1]?.at(-1)).toBe("true");
    await owner.studies.update({ studyId: blinded.studyId, status: "completed" });
    expect((await get(`/studies/${blinded.studyId}/events`, as(token.secret))).status).toBe(200);
  });

  it("is made only for studies whose data its owner may read, with an expiry of 1 to 365 days", async () => {
    const wizard = await s.apiAs(await s.signIn("wizard"));
    await expect(wizard.tokens.create({ name: "W", studyIds: [a.studyId], expiresInDays: 5 })).rejects.toMatchObject({
      code: "BAD_REQUEST",
      message: "Please correct: studyIds.0: not a study whose data you may read",
    });
    const outsider = await s.apiAs(await s.signIn("outsider"));
    await expect(outsider.tokens.create({ name: "O", studyIds: [a.studyId], expiresInDays: 5 })).rejects.toMatchObject({
      code: "BAD_REQUEST",
    });
    for (const expiresInDays of [0, 366, 1.5])
      await expect(owner.tokens.create({ name: "E", studyIds: [a.studyId], expiresInDays })).rejects.toMatchObject({
        code: "BAD_REQUEST",
      });
  });

  it("keeps only the secret's hash, and lets nobody but its owner revoke it", async () => {
    const made = await owner.tokens.create({ name: "Hashed", studyIds: [a.studyId], expiresInDays: 5 });
    const [row] = await s.db.select().from(accessTokens).where(eq(accessTokens.id, made.id));
    expect(row!.secretHash).toBe(hashTokenSecret(made.secret));
    expect(JSON.stringify(row)).not.toContain(made.secret);
    expect(JSON.stringify(await owner.tokens.list())).not.toContain(made.secret);
    const other = s.f.apiAs(await newPerson(s.db, "someone else"));
    await expect(other.tokens.revoke({ tokenId: made.id })).rejects.toMatchObject({ code: "NOT_FOUND" });
    expect((await get("/studies", as(made.secret))).status).toBe(200);
  });
});

describe("a token's caller in the API itself", () => {
  it("may only read data: any other procedure, even one its owner may call, is refused", async () => {
    const access = await contextFromToken(new Headers(as(tokenA)), "test");
    if (!("context" in access)) throw new Error(`refused: ${access.refused}`);
    const api = appRouter.createCaller(access.context);
    await expect(api.analysis.trials({ studyId: a.studyId })).resolves.toMatchObject({ columns: TRIAL_COLUMNS });
    const refused = { code: "FORBIDDEN", message: "An access token may only read analysis data." };
    await expect(api.tokens.list()).rejects.toMatchObject(refused);
    await expect(api.studies.mine()).rejects.toMatchObject(refused);
    await expect(api.trials.list({ studyId: a.studyId })).rejects.toMatchObject(refused);
    await expect(api.studies.update({ studyId: a.studyId, title: "Renamed" })).rejects.toMatchObject(refused);
    // Outside its scope, even a study its owner owns reads as unknown.
    await expect(api.studies.update({ studyId: b.studyId, title: "Renamed" })).rejects.toMatchObject({
      code: "NOT_FOUND",
    });
  });
});

describe("an unexpected failure", () => {
  it("answers 500 in plain JSON with a reference, the details only in the server's log", async () => {
    // A trial with no protocol at all cannot be read: the server's own fault, not the caller's.
    const [trial] = await s.db.select().from(trials).where(eq(trials.id, a.trialId));
    const [broken] = await s.db
      .insert(trials)
      .values({ studyId: a.studyId, experimentId: trial!.experimentId, participantId: a.participantId })
      .returning();
    const logged: string[] = [];
    const spy = vi.spyOn(console, "error").mockImplementation((...args: unknown[]) => void logged.push(args.join(" ")));
    const res = await get(`/trials/${broken!.id}/events`, as(tokenA));
    spy.mockRestore();
    await s.db.delete(trials).where(eq(trials.id, broken!.id));
    const { error } = (await res.json()) as { error: string };
    expect(res.status).toBe(500);
    const ref = /reference ([0-9a-f]{8})\.$/.exec(error)![1]!;
    expect(error).not.toMatch(/protocol|snapshot|select|at /);
    expect(logged.join("\n")).toContain(`[hristudio] error ${ref}: GET ${API_BASE}/trials/${broken!.id}/events`);
  });
});

describe("a participant who withdrew", () => {
  it("is left out of the study's tables, and one trial of theirs is refused by name (412)", async () => {
    const w = await studyWithTrial("Withdrawal study", "W-1");
    const token = (await owner.tokens.create({ name: "W", studyIds: [w.studyId], expiresInDays: 5 })).secret;
    await owner.participants.update({ participantId: w.participantId, consentStatus: "withdrawn" });
    for (const table of ["trials", "events", "samples", "annotations", "codes", "answers"])
      expect(await csvOf(await get(`/studies/${w.studyId}/${table}`, as(token)))).toHaveLength(1);
    const one = await get(`/trials/${w.trialId}/events`, as(token));
    expect([one.status, (await one.json()).error]).toEqual([
      412,
      "W-1 withdrew from the study: their data is excluded from analysis and exports.",
    ]);
  });
});

describe("the audit log", () => {
  it("records a token's creation, its revocation, and its first use of each day", async () => {
    const made = await owner.tokens.create({ name: "Audited", studyIds: [a.studyId], expiresInDays: 7 });
    const entries = () =>
      s.db
        .select({ action: auditLog.action, actorId: auditLog.actorId, details: auditLog.details })
        .from(auditLog)
        .where(eq(auditLog.target, made.id))
        .orderBy(auditLog.at);
    await get(`/studies/${a.studyId}/trials`, as(made.secret));
    await get(`/studies/${a.studyId}/events`, as(made.secret));
    // The next day's first use is written again.
    await s.db.update(accessTokens).set({ auditedOn: "2000-01-01" }).where(eq(accessTokens.id, made.id));
    await get(`/studies/${a.studyId}/answers`, as(made.secret));
    await owner.tokens.revoke({ tokenId: made.id });
    await owner.tokens.revoke({ tokenId: made.id });
    expect(await entries()).toEqual([
      {
        action: "token.create",
        actorId: s.f.people.owner.id,
        details: { name: "Audited", studies: ["Study A"], expiresAt: expect.any(String) },
      },
      {
        action: "token.use",
        actorId: s.f.people.owner.id,
        details: { name: "Audited", request: `GET ${API_BASE}/studies/${a.studyId}/trials` },
      },
      {
        action: "token.use",
        actorId: s.f.people.owner.id,
        details: { name: "Audited", request: `GET ${API_BASE}/studies/${a.studyId}/answers` },
      },
      { action: "token.revoke", actorId: s.f.people.owner.id, details: { name: "Audited" } },
    ]);
    const listed = (await owner.tokens.list()).find((t) => t.id === made.id)!;
    expect(listed.lastUsedAt).toBeInstanceOf(Date);
  });
});
