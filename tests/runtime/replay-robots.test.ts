// A replay takes its simulated robot the way a trial does, through the real
// runtime process, PostgreSQL and the simulated NAO6: while study A's live
// trial drives the one simulated robot, a member of study B replaying a trial
// of his own is refused in plain words that do not name A's trial, and the
// robot (and A's wizard) hear nothing of B; once A's trial has ended the replay
// plays; while it plays, a second replay (in this runtime process or another)
// and a trial starting on the robot are refused; once it is stopped, the trial
// starts. A study no simulated robot is available to replays on none.
import { and, eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import {
  experimentVersions,
  experiments,
  robots,
  studies,
  studyMembers,
  trialEvents,
  trials,
} from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { firstPartyPlugin } from "../support/plugins";
import { oneStep } from "../support/protocols";

const SECRET = "replay-robots-test-secret".padEnd(40, "x");
const nao = firstPartyPlugin("nao6-ros2.json");

const saying = (text: string) => oneStep([{ id: "hi", type: "say", parameters: { text } }]);

const A_LINE = "Study A's participant hears this.";
const B_LINE = "Study B's line, replayed.";
const BUSY = (doing: string) => `The simulated robot "Simulated robot 1" is ${doing}; replay when it is free.`;

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
let sim: Simulator;
let runtime: Awaited<ReturnType<typeof startRuntime>>;
/** A second runtime process on the same database, as a scaled-out deployment has. */
let other: Awaited<ReturnType<typeof startRuntime>>;
const sockets: TrialSocket[] = [];
const people: Record<string, string> = {};

/** A study with its members (role by person), and a trial-making function for its one experiment. */
async function study(title: string, line: string, members: Record<string, "wizard" | "observer" | "researcher">) {
  const [row] = await db.insert(studies).values({ title, status: "active" }).returning();
  for (const [who, role] of Object.entries(members)) {
    people[who] = (
      await createAccount(db, {
        name: who,
        email: `${who}@replay-robots.example.org`,
        password: "password-123",
        role: "researcher",
      })
    ).id;
    await db.insert(studyMembers).values({ studyId: row!.id, userId: people[who]!, role });
  }
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId: row!.id, name: "Greeting", robotId: "nao6-ros2" })
    .returning();
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot: saying(line), hash: title, robotId: "nao6-ros2" })
    .returning();
  return async () =>
    (
      await db
        .insert(trials)
        .values({ studyId: row!.id, experimentId: experiment!.id, versionId: version!.id })
        .returning()
    )[0]!.id;
}

async function open(who: string, trialId: string, on = runtime) {
  const socket = await connectTrial(on.url, signSocketToken({ userId: people[who]!, trialId }, SECRET));
  sockets.push(socket);
  return socket;
}

/** Everything the simulated robot was sent on its own topics (speech, gestures) and the replay topic since `from`. */
const heardSince = (from: number) =>
  sim.received
    .slice(from)
    .filter((r) => r.message.op === "publish" && r.message.topic !== "/rosout")
    .map((r) => ({ topic: String(r.message.topic), msg: r.message.msg }));
const spokenSince = (from: number) =>
  heardSince(from)
    .filter((h) => h.topic === "/speech")
    .map((h) => (h.msg as { data: string }).data);

async function replay(who: string, trialId: string, requestId: string, on = runtime) {
  const socket = await open(who, trialId, on);
  socket.send({ type: "replay", requestId, fromMs: 0, speed: 0.5 });
  return { socket, reply: await socket.next((m) => m.requestId === requestId) };
}

let startA: () => Promise<string>;
let trialB = "";

beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { msPerChar: 0 }) });
  // The one simulated robot, as npm start registers it: every study may use it.
  await db
    .insert(robots)
    .values({ name: "Simulated robot 1", simulated: true, rosbridgeUrl: sim.url, allStudies: true });
  startA = await study("Study A", A_LINE, { wizardA: "wizard" });
  const startB = await study("Study B", B_LINE, {
    wizardB: "wizard",
    observerB: "observer",
    researcherB: "researcher",
  });
  // HRI_SIMULATOR_URL as the launcher sets it: before, every replay went there, whoever drove the robot.
  runtime = await startRuntime(url, SECRET, { HRI_SIMULATOR_URL: sim.url });
  other = await startRuntime(url, SECRET, { HRI_SIMULATOR_URL: sim.url });

  // Study B's trial, run to its end on the robot.
  trialB = await startB();
  const wizard = await open("wizardB", trialB);
  expect(await wizard.command("b0", { kind: "start" })).toMatchObject({ type: "ack" });
  expect(await wizard.command("b1", { kind: "next" })).toMatchObject({ type: "ack" });
  expect(await wizard.command("b2", { kind: "next" })).toMatchObject({ type: "ack" });
  await wizard.next((m) => JSON.stringify(m).includes('"trial.completed"'));
  wizard.close();
  // As if it had lasted ten minutes: a replay of it plays until it is stopped.
  await db
    .update(trialEvents)
    .set({ relMs: 600_000 })
    .where(and(eq(trialEvents.trialId, trialB), eq(trialEvents.type, "trial.completed")));
}, 120_000);

afterAll(async () => {
  for (const s of sockets) s.close();
  runtime?.child.kill("SIGKILL");
  other?.child.kill("SIGKILL");
  await sim?.close();
  await close();
});

describe.sequential("a replay takes its robot the way a trial does", () => {
  let wizardA: TrialSocket;
  let liveA = "";
  let playing: TrialSocket;

  it("is refused while another study's live trial drives the simulated robot, which hears nothing of it", async () => {
    liveA = await startA();
    wizardA = await open("wizardA", liveA);
    expect(await wizardA.command("a0", { kind: "start" })).toMatchObject({ type: "ack" });
    const mark = sim.received.length;

    const { reply } = await replay("observerB", trialB, "r1");
    expect(reply).toEqual({ type: "rejected", requestId: "r1", reason: BUSY("running another trial") });
    // Refused before anything was sent: not B's line, not a replay announcement.
    expect(heardSince(mark)).toEqual([]);
    expect(JSON.stringify(wizardA.messages)).not.toContain(B_LINE);
    expect(reply.reason).not.toMatch(/Study A|Greeting/);

    // A's trial goes on as its own: its line, and only its line, reaches the robot.
    expect(await wizardA.command("a1", { kind: "next" })).toMatchObject({ type: "ack" });
    await expect.poll(() => spokenSince(mark)).toEqual([A_LINE]);
  });

  it("plays once that trial has ended", async () => {
    expect(await wizardA.command("a2", { kind: "next" })).toMatchObject({ type: "ack" });
    await wizardA.next((m) => JSON.stringify(m).includes('"trial.completed"'));
    const mark = sim.received.length;
    const { socket, reply } = await replay("observerB", trialB, "r2");
    expect(reply).toMatchObject({ type: "ack" });
    playing = socket;
    await expect.poll(() => spokenSince(mark)).toEqual([B_LINE]);
  });

  it("while it plays, a second replay is refused, and so is a trial starting on its robot", async () => {
    const { reply } = await replay("researcherB", trialB, "r3");
    expect(reply).toEqual({ type: "rejected", requestId: "r3", reason: BUSY("playing another replay") });
    // Another runtime process sees the robot held too (it cannot tell by whom).
    const elsewhere = await replay("researcherB", trialB, "r3b", other);
    expect(elsewhere.reply).toEqual({
      type: "rejected",
      requestId: "r3b",
      reason: BUSY("busy with another trial or replay"),
    });

    const next = await startA();
    const wizard = await open("wizardA", next);
    expect(await wizard.command("c0", { kind: "start" })).toMatchObject({
      type: "rejected",
      reason:
        'The robot "Simulated robot 1" is being driven by a replay of a finished trial. This trial can start once it is free.',
    });
    // The first replay was not disturbed by either.
    expect(playing.messages.filter((m) => m.type === "replay" && m.playing === false)).toEqual([]);

    // Stopped, it gives the robot back: the trial starts.
    playing.send({ type: "replay_stop", requestId: "s" });
    expect(await playing.next((m) => m.requestId === "s")).toMatchObject({ type: "ack" });
    expect(await wizard.command("c1", { kind: "start" })).toMatchObject({ type: "ack" });
    const [row] = await db.select({ status: trials.status }).from(trials).where(eq(trials.id, next));
    expect(row!.status).toBe("in_progress");
  });

  it("is refused when no simulated robot is available to the study, saying who can make one available", async () => {
    await db.update(robots).set({ allStudies: false });
    try {
      const { reply } = await replay("observerB", trialB, "r4");
      expect(reply).toEqual({
        type: "rejected",
        requestId: "r4",
        reason:
          "No simulated robot is available to this study, so the replay did not start: an administrator makes one available (Administration → Robots).",
      });
    } finally {
      await db.update(robots).set({ allStudies: true });
    }
  });
});
