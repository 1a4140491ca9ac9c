// Observers code a running trial live over the real runtime socket: each key
// press is timed on the trial's clock and lands in the observer's own tier,
// states of one set exclude one another, and nobody else hears of it.
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, expect, it } from "vitest";
import { codeEvents } from "../../src/store/schema";
import { socketFixture } from "../support/socket-fixture";
import type { TrialSocket } from "../support/socket";

let f: Awaited<ReturnType<typeof socketFixture>>;
beforeAll(async () => {
  f = await socketFixture();
});
afterAll(async () => f?.stop());

const press = (
  socket: TrialSocket,
  schemeVersionId: string,
  setId: string,
  codeId: string,
  modifiers: string[] = [],
) => {
  const requestId = crypto.randomUUID();
  socket.send({ type: "code", requestId, schemeVersionId, setId, codeId, modifiers });
  return socket.next((m) => m.requestId === requestId && (m.type === "codes" || m.type === "rejected"));
};

it("marks points and states in each observer's own tier, one state of a set at a time", async () => {
  const trialId = await f.a.trial(f.a.people.wizard!, "live");
  const observer = await f.open("observer", trialId);
  const researcher = await f.open("researcher", trialId);
  const v = f.a.schemeVersionId;

  const robot = await press(observer, v, "gaze", "robot");
  expect(robot).toMatchObject({
    type: "codes",
    codes: [{ setId: "gaze", codeId: "robot", kind: "state", endMs: null }],
  });
  const startedAt = (robot.codes as Array<{ startMs: number }>)[0]!.startMs;
  expect(startedAt).toBeGreaterThanOrEqual(0);
  // A state of the same set ends the one that held, at the same moment it starts.
  const task = (await press(observer, v, "gaze", "task")).codes as Array<Record<string, unknown>>;
  expect(task.map((c) => [c.codeId, c.endMs === null])).toEqual([
    ["robot", false],
    ["task", true],
  ]);
  expect(task[0]!.endMs).toBe(task[1]!.startMs);
  expect(await press(observer, v, "expression", "smile", ["laugh"])).toMatchObject({
    codes: [{ codeId: "smile", kind: "point", endMs: null, modifiers: ["laugh"] }],
  });
  // The same key again ends the state.
  expect(await press(observer, v, "gaze", "task")).toMatchObject({
    codes: [{ codeId: "task", endMs: expect.any(Number) }],
  });
  // The researcher's own tier: their gaze state does not end the observer's.
  await press(researcher, v, "gaze", "away");

  expect(await press(observer, v, "gaze", "blink")).toMatchObject({
    type: "rejected",
    reason: "“Participant engagement” has no code gaze/blink.",
  });
  expect(await press(observer, v, "expression", "smile", ["grin"])).toMatchObject({
    type: "rejected",
    reason: "“Smile” has no modifier “grin”.",
  });

  const rows = await f.db.select().from(codeEvents).where(eq(codeEvents.trialId, trialId));
  const tier = (who: string) =>
    rows
      .filter((r) => r.observerId === who)
      .sort((a, b) => a.startMs - b.startMs || a.codeId.localeCompare(b.codeId))
      .map((r) => [r.codeId, r.endMs === null ? "open" : "ended"]);
  expect(tier(f.a.people.observer!)).toEqual(
    expect.arrayContaining([
      ["robot", "ended"],
      ["task", "ended"],
      ["smile", "open"],
    ]),
  );
  expect(tier(f.a.people.observer!)).toHaveLength(3);
  expect(tier(f.a.people.researcher!)).toEqual([["away", "open"]]);
  // Observers code independently: no one hears of another's codes.
  expect(researcher.messages.filter((m) => m.type === "codes")).toHaveLength(1);
  observer.close();
  researcher.close();
});

it("refuses codes before the trial starts and after it ends, and another study's scheme", async () => {
  const scheduled = await f.a.trial(f.a.people.wizard!, "scheduled");
  const completed = await f.a.trial(f.a.people.wizard!, "completed");
  const live = await f.a.trial(f.a.people.wizard!, "live");
  for (const [trialId, reason] of [
    [scheduled, "The trial has not started yet: codes are timed from its start."],
    [completed, "The trial has ended: code it on its analysis page, against the recording."],
  ] as const) {
    const socket = await f.open("observer", trialId);
    expect(await press(socket, f.a.schemeVersionId, "gaze", "robot")).toMatchObject({ type: "rejected", reason });
    socket.close();
  }
  const socket = await f.open("observer", live);
  expect(await press(socket, f.b.schemeVersionId, "gaze", "robot")).toMatchObject({
    type: "rejected",
    reason: "That coding scheme is not one of this study's.",
  });
  socket.close();
  expect(await f.db.select().from(codeEvents).where(eq(codeEvents.trialId, live))).toEqual([]);
});
