// Two runtime processes on one database, a dozen simulated robots over real
// sockets, the real roslib client: trials opened at once through both each
// take a robot of their own.
import type { ChildProcess } from "node:child_process";
import { and, eq, inArray } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { createAccount } from "../../src/server/auth/accounts";
import type { Simulator } from "../../src/robots/simulator";
import { createDatabase } from "../../src/store/client";
import {
  experimentVersions,
  experiments,
  mediaRecordings,
  studies,
  studyMembers,
  trialEvents,
  trials,
} from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { registerRobots } from "../support/robots";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";

const SECRET = "runtimes-together-test-secret".padEnd(40, "x");
const ROBOTS = 12;
const TRIALS = 10;

const saying = (text: string): ProtocolSnapshot => ({
  schemaVersion: 5,
  experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
  steps: [
    {
      id: "s1",
      name: "Greeting",
      description: "",
      actions: [{ id: "hi", type: "say", name: "", parameters: { text }, parallelGroup: null }],
    },
    {
      id: "s2",
      name: "Goodbye",
      description: "",
      actions: [{ id: "bye", type: "say", name: "", parameters: { text: `${text}, goodbye` }, parallelGroup: null }],
    },
  ],
});

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
const sims = new Map<string, Simulator>();
const sockets: TrialSocket[] = [];
const runtimes: Array<{ url: string; child: ChildProcess }> = [];
let wizardId = "";
let studyId = "";

/** A trial of its own experiment; `assigned: false` leaves it for the first wizard to start it to claim. */
async function newTrial(text: string, assigned = true) {
  const [experiment] = await db.insert(experiments).values({ studyId, name: text, robotId: "simulated" }).returning();
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot: saying(text), hash: text, robotId: "simulated" })
    .returning();
  const [trial] = await db
    .insert(trials)
    .values({ studyId, experimentId: experiment!.id, versionId: version!.id, wizardId: assigned ? wizardId : null })
    .returning();
  return trial!.id;
}

async function open(runtimeUrl: string, trialId: string) {
  const socket = await connectTrial(runtimeUrl, signSocketToken({ userId: wizardId, trialId }, SECRET));
  sockets.push(socket);
  return socket;
}

/** The simulated robot the trial was given. */
async function simOf(trialId: string): Promise<Simulator> {
  const [row] = await db.select({ robot: trials.assignedRobotId }).from(trials).where(eq(trials.id, trialId));
  return sims.get(row!.robot!)!;
}

const published = (sim: Simulator, topic: string) =>
  sim.received
    .filter((r) => r.message.op === "publish" && r.message.topic === topic)
    .map((r) => (r.message.msg as { data: unknown }).data);

beforeAll(async () => {
  const [study] = await db.insert(studies).values({ title: "Many robots", status: "active" }).returning();
  studyId = study!.id;
  wizardId = (
    await createAccount(db, { name: "Wizard", email: "w@example.org", password: "password-123", role: "researcher" })
  ).id;
  await db.insert(studyMembers).values({ studyId, userId: wizardId, role: "wizard" });
  const names = Array.from({ length: ROBOTS }, (_, i) => `Sim ${String(i).padStart(2, "0")}`);
  for (const robot of await registerRobots(db, studyId, names)) sims.set(robot.id, robot.sim);
  for (let i = 0; i < 2; i++) runtimes.push(await startRuntime(url, SECRET));
}, 120_000);

afterAll(async () => {
  for (const s of sockets) s.close();
  for (const r of runtimes) r.child.kill("SIGKILL");
  for (const sim of sims.values()) await sim.close();
  await close();
});

describe.sequential("several runtimes, many robots", () => {
  const opened: Array<{ trialId: string; socket: TrialSocket }> = [];

  it("gives ten trials opened at once through two runtimes ten robots, and starts every one", {
    timeout: 60_000,
  }, async () => {
    const ids = await Promise.all(Array.from({ length: TRIALS }, (_, i) => newTrial(`Hello ${i}`)));
    // Half through each runtime, every hello at the same moment.
    const sockets = await Promise.all(ids.map((id, i) => open(runtimes[i % 2]!.url, id)));
    ids.forEach((trialId, i) => opened.push({ trialId, socket: sockets[i]! }));
    const names = await Promise.all(
      sockets.map(async (s) => (await s.next((m) => m.type === "robot" && "name" in m)).name),
    );
    expect(new Set(names).size).toBe(TRIALS);
    const started = await Promise.all(sockets.map((s, i) => s.command(`start-${i}`, { kind: "start" })));
    expect(started.map((r) => [r.type, r.reason])).toEqual(ids.map(() => ["ack", undefined]));
    const assigned = await db.select({ robot: trials.assignedRobotId }).from(trials).where(inArray(trials.id, ids));
    expect(new Set(assigned.map((a) => a.robot)).size).toBe(TRIALS);
    await Promise.all(sockets.map((s, i) => s.command(`next-${i}`, { kind: "next" })));
    for (const [i, trialId] of ids.entries())
      await expect.poll(async () => published(await simOf(trialId), "/speech")).toEqual([`Hello ${i}`]);
  });

  it("serves, after a restart, every new wizard: commands of trials the other runtime runs reach the robot and are acked", {
    timeout: 90_000,
  }, async () => {
    const killed = runtimes[0]!.child;
    await new Promise((exited) => {
      killed.once("exit", exited);
      killed.kill("SIGKILL");
    });
    runtimes[0] = await startRuntime(url, SECRET);
    // Every trial through the restarted runtime: the other's (odd) through it, the killed one's taken over.
    const again = await Promise.all(opened.map(({ trialId }) => open(runtimes[0]!.url, trialId)));
    // Into the second step, then its line.
    const answers = await Promise.all(
      again.map(async (s, i) => [
        await s.command(`on-${i}`, { kind: "next" }),
        await s.command(`bye-${i}`, { kind: "next" }),
      ]),
    );
    expect(answers.flat().map((a) => [a.type, a.reason])).toEqual(answers.flat().map(() => ["ack", undefined]));
    for (const [i, { trialId }] of opened.entries())
      await expect
        .poll(async () => published(await simOf(trialId), "/speech"))
        .toEqual([`Hello ${i}`, `Hello ${i}, goodbye`]);
    expect(again.flatMap((s) => s.messages).filter((m) => /reload/i.test(JSON.stringify(m)))).toEqual([]);
  });

  it("stops the robot of a trial the other runtime runs, straight from the runtime the stop reached and through the owner", {
    timeout: 30_000,
  }, async () => {
    const { trialId } = opened[1]!;
    const sim = await simOf(trialId);
    const wizard = await open(runtimes[0]!.url, trialId);
    const stopped = await wizard.command("stop", { kind: "emergency_stop" });
    expect(stopped).toMatchObject({ type: "ack" });
    await wizard.next((m) => m.type === "halted" && m.requestId === "stop");
    // Two links sent it: the one this runtime keeps for stops, and the owner's.
    const senders = () =>
      new Set(
        sim.received
          .filter((r) => r.message.op === "publish" && r.message.topic === "/speech_stop")
          .map((r) => r.connection),
      ).size;
    await expect.poll(senders).toBe(2);
  });

  it.each([
    ["the runtime that runs the trial", 1],
    ["the runtime that does not run the trial", 0],
  ])(
    "carries out a wizard's commands sent back to back through %s in the order sent, those that read the database first too",
    { timeout: 60_000 },
    async (_, through) => {
      // Unassigned: the start claims it for the wizard, a read and a write before it enters the trial's queue.
      const trialId = await newTrial(`Order ${through}`, false);
      const recordings = await db
        .insert(mediaRecordings)
        .values(
          ["a", "b"].map((k) => ({
            trialId,
            kind: "video" as const,
            storageKey: `order-${k}`,
            mimeType: "video/webm",
          })),
        )
        .returning({ id: mediaRecordings.id });
      // The trial's first page opens it where it is asked for: through the owner, or the other runtime forwards.
      const owner = await open(runtimes[1]!.url, trialId);
      await owner.next((m) => m.type === "robot" && m.connected === true, 10_000);
      const wizard = through === 1 ? owner : await open(runtimes[through]!.url, trialId);
      // A recording's owner is read before it is logged: one among the first lines and one half way.
      const commands: Array<{ logged: string; command: Record<string, unknown> }> = [
        { logged: "started", command: { kind: "start" } },
        ...Array.from({ length: 100 }, (_, i) => ({
          logged: `line ${i}`,
          command: { kind: "unscripted", actionType: "say", parameters: { text: `line ${i}` } },
        })),
      ];
      for (const [at, recording] of [
        [3, recordings[0]!],
        [52, recordings[1]!],
      ] as const)
        commands.splice(at, 0, {
          logged: `recording ${recording.id}`,
          command: { kind: "recording", recordingId: recording.id, offsetMs: 0 },
        });
      // Sent as fast as the socket takes them, none waiting for the last's answer.
      const answers = await Promise.all(commands.map((c, i) => wizard.command(`order-${through}-${i}`, c.command)));
      expect(answers.map((a) => a.type)).toEqual(commands.map(() => "ack"));
      const logged = await db
        .select({ type: trialEvents.type, payload: trialEvents.payload })
        .from(trialEvents)
        .where(
          and(
            eq(trialEvents.trialId, trialId),
            inArray(trialEvents.type, ["trial.started", "action.requested", "recording.started"]),
          ),
        )
        .orderBy(trialEvents.seq);
      const named = logged.map(({ type, payload }) => {
        const p = payload as { parameters?: { text?: string }; recordingId?: string };
        if (type === "trial.started") return "started";
        return type === "recording.started" ? `recording ${p.recordingId}` : p.parameters?.text;
      });
      expect(named).toEqual(commands.map((c) => c.logged));
      const sim = await simOf(trialId);
      const lines = commands.map((c) => c.logged).filter((l) => l.startsWith("line "));
      await expect.poll(() => published(sim, "/speech").filter((t) => String(t).startsWith("line "))).toEqual(lines);
    },
  );

  it("tells a page on the runtime that does not run the trial of its robot: its name, and when it drops and comes back", {
    timeout: 30_000,
  }, async () => {
    const trialId = await newTrial("Status");
    // Opened first through one runtime, which runs it; then through the other.
    const owner = await open(runtimes[1]!.url, trialId);
    await owner.next((m) => m.type === "robot" && m.connected === true, 10_000);
    const elsewhere = await open(runtimes[0]!.url, trialId);
    const first = await elsewhere.next((m) => m.type === "robot" && "name" in m);
    expect(first).toMatchObject({ connected: true, name: expect.stringMatching(/^Sim \d\d$/) });
    const sim = await simOf(trialId);
    sim.faults.refuseConnections(true);
    sim.faults.dropConnections();
    await elsewhere.next((m) => m.type === "robot" && m.connected === false, 15_000);
    sim.faults.refuseConnections(false);
    await expect
      .poll(() => elsewhere.messages.filter((m) => m.type === "robot").at(-1), { timeout: 20_000 })
      .toMatchObject({ connected: true });
  });
});
