// A runtime process frozen (SIGSTOP) for 20 s while the wizard keeps asking
// (issue 25): the page, through its real socket and heartbeat, shows the
// runtime silent within 2 s; the commands that waited in the frozen
// process's socket are, once it goes on, older than their freshness limit
// counted from when the wizard asked (the page's clock, less the offset the
// heartbeat measured), so none reaches the robot: the wizard is told each was
// not sent, and a say asked for afresh is spoken. What the robot received is
// read at the simulated robot. About 30 s long.
import type { ChildProcess } from "node:child_process";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import type { RuntimeLink } from "../../src/core/socket/heartbeat";
import { startHeartbeat } from "../../src/features/execution/heartbeat";
import { simulatedRobot, type Simulator, startSimulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { robotStudies, robots, studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { trialOf } from "../support/trial-rows";

const SECRET = "frozen-runtime-test-secret".padEnd(40, "x");
const FROZEN_MS = 20_000;

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 2 });
let runtime: { url: string; child: ChildProcess };
let sim: Simulator;
let page: TrialSocket | null = null;
let frozen = false;

const snapshot: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "E", description: "", robotId: "simulated" },
  steps: [{ id: "s1", name: "One", description: "", actions: [] }],
};

beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(firstPartyPlugin("simulated.json")) });
  runtime = await startRuntime(url, SECRET);
  runtime.child.stderr!.on("data", (d) => process.stderr.write(`RT: ${d}`));
}, 120_000);

afterAll(async () => {
  page?.close();
  if (frozen) process.kill(runtime.child.pid!, "SIGCONT");
  runtime?.child.kill("SIGKILL");
  await sim?.close();
  await close();
});

const spoken = () =>
  sim.received
    .filter((r) => r.message.op === "publish" && r.message.topic === "/speech")
    .map((r) => (r.message.msg as { data: string }).data);

const say = (text: string) => ({ kind: "unscripted", actionType: "say", parameters: { text } });

describe("a runtime frozen with the wizard's commands waiting", () => {
  it("shows silent within 2 s, and sends the robot nothing older than its limit once it goes on", {
    timeout: 90_000,
  }, async () => {
    const [study] = await db.insert(studies).values({ title: "Frozen runtime", status: "active" }).returning();
    const wizard = await createAccount(db, {
      name: "Wizard",
      email: "frozen-runtime@example.org",
      password: "password-123",
      role: "researcher",
    });
    await db.insert(studyMembers).values({ studyId: study!.id, userId: wizard.id, role: "wizard" });
    const [robot] = await db.insert(robots).values({ name: "Sim", simulated: true, rosbridgeUrl: sim.url }).returning();
    await db.insert(robotStudies).values({ robotId: robot!.id, studyId: study!.id });
    const trialId = await trialOf(db, { studyId: study!.id, wizardId: wizard.id, snapshot, withParticipant: true });
    page = await connectTrial(runtime.url, signSocketToken({ userId: wizard.id, trialId }, SECRET));
    const socket = page;
    const shown: RuntimeLink[] = [];
    const heartbeat = startHeartbeat(socket.send, (link) => shown.push(link));
    socket.listen((m) => heartbeat.heard(m));
    // Two answered pings: the runtime has measured the page's clock.
    await socket.next((m) => m.type === "pong");
    await expect.poll(() => socket.messages.filter((m) => m.type === "pong").length).toBeGreaterThanOrEqual(2);
    /** As the page sends a command: with the moment the wizard asked, on the page's clock. */
    const ask = (requestId: string, command: Record<string, unknown>) =>
      socket.send({ type: "command", requestId, command, at: Date.now() });
    const outcome = (requestId: string, timeout = 30_000) =>
      socket.next((m) => m.requestId === requestId && (m.type === "ack" || m.type === "rejected"), timeout);

    expect((await socket.command("start", { kind: "start" })).type).toBe("ack");
    ask("before", say("Before the freeze"));
    expect(await outcome("before")).toMatchObject({ type: "ack" });
    await expect.poll(() => spoken()).toEqual(["Before the freeze"]);

    process.kill(runtime.child.pid!, "SIGSTOP");
    frozen = true;
    // Asked while it is frozen: each waits in the process's socket, unread.
    for (let i = 1; i <= 5; i++) ask(`queued-${i}`, say(`Queued ${i}`));
    await expect.poll(() => shown.at(-1), { timeout: 2000, interval: 50 }).toBe("silent");
    await new Promise((r) => setTimeout(r, FROZEN_MS));
    frozen = false;
    process.kill(runtime.child.pid!, "SIGCONT");

    for (let i = 1; i <= 5; i++)
      expect(await outcome(`queued-${i}`)).toMatchObject({
        type: "rejected",
        reason: expect.stringMatching(/^Not sent: asked for 2\d\.\d s ago, longer than the 3 s/),
      });
    await expect.poll(() => shown.at(-1), { timeout: 10_000 }).toBe("live");
    ask("after", say("After the freeze"));
    const afterOutcome = await outcome("after");
    expect(afterOutcome).toMatchObject({ type: "ack" });
    await expect.poll(() => spoken().at(-1)).toBe("After the freeze");
    expect(spoken()).toEqual(["Before the freeze", "After the freeze"]);
    heartbeat.stop();
  });
});
