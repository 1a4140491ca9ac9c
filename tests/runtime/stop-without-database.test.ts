// Safety before logging: an emergency stop reaches the robot while the
// database is frozen (every PostgreSQL process SIGSTOPped, as a hung server
// would be), and what the wizard asked for before the stop never reaches the
// robot after it. The database here is a PostgreSQL of its own, so freezing it
// stops no other test; the runtime is the real process, the robot the
// simulated one, reached over the real roslib client.
import { rm } from "node:fs/promises";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { startEmbeddedPostgres, type EmbeddedDatabase } from "../../src/store/embedded";
import { migrateDatabase } from "../../src/store/migrate";
import { experimentVersions, experiments, studies, studyMembers, trials } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { signalDatabase as signalToDatabase } from "../support/frozen-postgres";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { scratchFolder } from "../support/scratch";
import { connectTrial, type TrialSocket } from "../support/socket";

const SECRET = "stop-without-database-secret".padEnd(40, "x");
const plugin = firstPartyPlugin("simulated.json");

const protocol: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
  steps: [
    {
      id: "walk",
      name: "Walk",
      description: "",
      actions: [
        { id: "go", type: "move", name: "", parameters: { direction: "forward", speed: 0.4 }, parallelGroup: null },
      ],
    },
    {
      id: "talk",
      name: "Talk",
      description: "",
      actions: [{ id: "late", type: "say", name: "", parameters: { text: "Too late" }, parallelGroup: null }],
    },
  ],
};

let dataDir = "";
let pg: EmbeddedDatabase;
let database: ReturnType<typeof createDatabase>;
let sim: Simulator;
let runtime: Awaited<ReturnType<typeof startRuntime>>;
let wizard: TrialSocket;

const signalDatabase = (signal: "SIGSTOP" | "SIGCONT") => signalToDatabase(dataDir, signal);

beforeAll(async () => {
  dataDir = scratchFolder("stop-pg-");
  pg = await startEmbeddedPostgres({ dataDir });
  await migrateDatabase(pg.url);
  database = createDatabase(pg.url);
  const { db } = database;
  const [study] = await db.insert(studies).values({ title: "Stop", status: "active" }).returning();
  const person = await createAccount(db, {
    name: "Wizard",
    email: "wizard@example.org",
    password: "password-123",
    role: "researcher",
  });
  await db.insert(studyMembers).values({ studyId: study!.id, userId: person.id, role: "wizard" });
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId: study!.id, name: "E", robotId: "simulated" })
    .returning();
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot: protocol, hash: "h", robotId: "simulated" })
    .returning();
  const [trial] = await db
    .insert(trials)
    .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id, wizardId: person.id })
    .returning();

  sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  runtime = await startRuntime(pg.url, SECRET, { HRI_ROSBRIDGE_URL: sim.url });
  wizard = await connectTrial(runtime.url, signSocketToken({ userId: person.id, trialId: trial!.id }, SECRET));
}, 120_000);

afterAll(async () => {
  await signalDatabase("SIGCONT").catch(() => {});
  wizard?.close();
  runtime?.child.kill("SIGKILL");
  await sim?.close();
  await database?.close();
  await pg?.stop();
  await rm(dataDir, { recursive: true, force: true });
});

const publishes = (topic: string) =>
  sim.received.filter((r) => r.message.op === "publish" && r.message.topic === topic).map((r) => r.message.msg);

describe("an emergency stop with the database frozen", () => {
  it("stops the robot at once, drops what was asked before it, and logs the stop once the database is back", {
    timeout: 60_000,
  }, async () => {
    const still = { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } };
    expect(await wizard.command("r1", { kind: "start" })).toMatchObject({ type: "ack" });
    expect(await wizard.command("r2", { kind: "next" })).toMatchObject({ type: "ack" });
    await expect.poll(() => publishes("/cmd_vel").length).toBe(1);
    expect(publishes("/cmd_vel")[0]).not.toEqual(still);

    expect(await wizard.command("r3", { kind: "next" })).toMatchObject({ type: "ack" });

    await signalDatabase("SIGSTOP");
    // Asked for while the database is away: the step's speech (logged as asked for, then held by the
    // frozen database) and a line of the wizard's own (waiting its turn). Neither may reach the robot
    // after the stop.
    wizard.send({ type: "command", requestId: "r4", command: { kind: "next" } });
    wizard.send({
      type: "command",
      requestId: "r5",
      command: { kind: "unscripted", actionType: "say", parameters: { text: "Also too late" } },
    });
    wizard.send({ type: "command", requestId: "stop", command: { kind: "emergency_stop" } });
    await wizard.next((m) => m.type === "halted" && m.requestId === "stop");
    // The halt is on the robot while the database is still frozen.
    await expect.poll(() => publishes("/cmd_vel").at(-1)).toEqual(still);
    expect(wizard.messages.some((m) => m.requestId === "stop" && m.type === "ack")).toBe(false);

    await signalDatabase("SIGCONT");
    expect(await wizard.next((m) => m.requestId === "r5", 30_000)).toMatchObject({
      type: "rejected",
      reason: "Not carried out: the robot was stopped after you asked for this.",
    });
    expect(await wizard.next((m) => m.requestId === "stop" && m.type === "ack", 30_000)).toMatchObject({ type: "ack" });
    expect(publishes("/speech")).toEqual([]);
    const logged = wizard.messages.flatMap((m) =>
      m.type === "events" ? (m.events as Array<{ type: string }>).map((e) => e.type) : [],
    );
    expect(logged).toContain("trial.emergency_stop");
    // The speech the stop overtook is in the log as never sent.
    await wizard.next(
      (m) => m.type === "events" && (m.events as Array<{ type: string }>).some((e) => e.type === "action.not_sent"),
    );
    const notSent = wizard.messages.flatMap((m) =>
      m.type === "events"
        ? (m.events as Array<{ type: string; reason?: string }>).filter((e) => e.type === "action.not_sent")
        : [],
    );
    expect(notSent).toMatchObject([
      { actionId: "late", reason: "Not sent: the robot was stopped before this reached it." },
    ]);
    expect(publishes("/speech")).toEqual([]);
  });

  it("answers the wizard by the log's deadline while it is stuck, and refuses what comes after at once", {
    timeout: 60_000,
  }, async () => {
    await signalDatabase("SIGSTOP");
    wizard.send({
      type: "command",
      requestId: "held",
      command: { kind: "note", text: "written once the log is back" },
    });
    // Answered while the database is still frozen: the write under way never returns, the wizard is not kept waiting.
    expect(await wizard.next((m) => m.requestId === "held", 30_000)).toMatchObject({
      type: "rejected",
      reason: expect.stringMatching(/^The trial log did not answer in time/),
    });
    // Asked while the log has been stuck past its deadline: refused at once, the database still frozen.
    expect(await wizard.command("refused", { kind: "note", text: "never written" })).toEqual({
      type: "rejected",
      requestId: "refused",
      reason:
        "The trial log is not answering (the database is unavailable), so nothing was done and the robot was not told. Try again in a moment.",
    });
    await signalDatabase("SIGCONT");
    // The held note lands once the database thaws, and the wizard sees it in the log, as the answer said.
    await wizard.next(
      (m) =>
        m.type === "events" &&
        (m.events as Array<{ text?: string }>).some((e) => e.text === "written once the log is back"),
      30_000,
    );
    const notes = wizard.messages.flatMap((m) =>
      m.type === "events"
        ? (m.events as Array<{ type: string; text?: string }>).filter((e) => e.type === "note.added").map((e) => e.text)
        : [],
    );
    expect(notes).not.toContain("never written");
  });

  it("ends on SIGTERM though a command is stuck on the frozen database", { timeout: 30_000 }, async () => {
    await signalDatabase("SIGSTOP");
    wizard.send({ type: "command", requestId: "stuck", command: { kind: "resume" } });
    await new Promise((r) => setTimeout(r, 200));
    const exited = new Promise<number | null>((resolve) => runtime.child.once("exit", (code) => resolve(code)));
    runtime.child.kill("SIGTERM");
    // Bounded shutdown: the runtime gives up on the stuck command rather than waiting for ever.
    expect(await exited).toBe(1);
    await signalDatabase("SIGCONT");
  });
});
