// The analysis page's log comes from its own route (GET /api/trials/<id>/events),
// written as it is read: the same events as the API's trials.events, at a long
// trial's size; a plain refusal where the log may not be read; and a log that
// cannot be read part-way fails, never ending as a shorter log that parses.
import { afterAll, expect, it } from "vitest";
import { unscriptedLog } from "../../bench/support";
import { ORIGIN, routeServer } from "../support/routes";
import { publishedVersion } from "./fixture";

const s = await routeServer();
afterAll(s.close);
const { db, f } = s;
const owner = f.api("owner");
const route = await import("../../src/app/api/trials/[trialId]/events/route");
const signedIn = await s.signIn("owner");

/** Three pages of the log's and a part of a fourth (see LOG_PAGE in event-store.ts). */
const EVENTS = 16_001;

const get = (trialId: string) =>
  route.GET(new Request(`${ORIGIN}/api/trials/${trialId}/events`, { headers: signedIn }), {
    params: Promise.resolve({ trialId }),
  });

/** A completed trial of `count` events (unscripted lines, with quotes, line breaks and non-Latin text in notes). */
async function seededTrial(count: number) {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  const t0 = new Date(Date.now() - 3_600_000);
  const rows = unscriptedLog(trial.id, count, t0, (i) => i * 100).map((row, i) =>
    i % 700 === 350
      ? {
          ...row,
          type: "note.added",
          action_id: null,
          payload: JSON.stringify({ type: "note.added", text: `"quoted" \\ line ${i}\nnext ✓ 中文` }),
          deviation: false,
        }
      : row,
  );
  const sql = db.$client;
  for (let start = 0; start < rows.length; start += 2_500)
    await sql`insert into trial_events ${sql(rows.slice(start, start + 2_500), "trial_id", "seq", "type", "server_time", "rel_ms", "actor_id", "step_id", "action_id", "payload", "deviation")}`;
  await sql`update trials set status = 'completed', t0 = ${t0.toISOString()}::timestamptz where id = ${trial.id}`;
  return { trial, study };
}

it("answers with the trial's whole log as JSON, the same events as the API's trials.events", async () => {
  const { trial } = await seededTrial(EVENTS);
  const res = await get(trial.id);
  expect(res.status).toBe(200);
  expect(res.headers.get("content-type")).toBe("application/json; charset=utf-8");
  const log = (await res.json()) as Array<{ seq: number }>;
  expect(log).toHaveLength(EVENTS);
  expect(log).toEqual(await owner.trials.events({ trialId: trial.id }));
  expect(log.map((e) => e.seq)).toEqual(Array.from({ length: EVENTS }, (_, i) => i + 1));
});

it("answers a trial without events with an empty list", async () => {
  const study = await f.newStudy();
  const { version } = await publishedVersion(owner, study.id);
  const trial = await owner.trials.create({ versionId: version.id });
  const res = await get(trial.id);
  expect(res.status).toBe(200);
  expect(await res.json()).toEqual([]);
});

it("refuses in plain words a withdrawn participant's trial, and an id that is no trial's", async () => {
  const { trial, study } = await seededTrial(10);
  const participant = await owner.participants.create({
    studyId: study.id,
    code: "W-1",
    consentStatus: "given",
    consentDate: new Date(),
  });
  await db.$client`update trials set participant_id = ${participant.id} where id = ${trial.id}`;
  await owner.participants.update({ participantId: participant.id, consentStatus: "withdrawn" });
  const withdrawn = await get(trial.id);
  expect(withdrawn.status).toBe(412);
  expect(await withdrawn.text()).toMatch(/withdr/i);
  for (const id of [crypto.randomUUID(), "not-a-trial"]) {
    const res = await get(id);
    expect([400, 404]).toContain(res.status);
    expect(await res.text()).not.toMatch(/select|trial_events|at .+\.ts/i);
  }
});

it("fails the answer when the log cannot be read part-way: it never ends as a shorter log", async () => {
  const { trial } = await seededTrial(EVENTS);
  const reader = (await get(trial.id)).body!.getReader();
  expect((await reader.read()).done).toBe(false);
  // The log goes away after the first events have left (the headers with them).
  await db.$client`alter table trial_events rename to trial_events_away`;
  try {
    let failed: unknown;
    try {
      for (let read = await reader.read(); !read.done; read = await reader.read());
    } catch (error) {
      failed = error;
    }
    expect(failed).toBeInstanceOf(Error);
    expect((failed as Error).message).toMatch(/^The log of trial .+ could not be finished$/);
  } finally {
    await db.$client`alter table trial_events_away rename to trial_events`;
  }
});
