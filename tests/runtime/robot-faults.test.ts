// One bad robot record stays in its own trial, in the real runtime process:
// study B's NAO is registered with an SSH key file that is not a key; its
// wizard's SSH action fails with that reason, while study A's live trial on
// a simulated robot goes on (its socket open, its next command acknowledged
// and carried out) and the runtime keeps running. Before, ssh2's throw on the
// key became an unhandled rejection that ended the runtime and every trial.
import type { ChildProcess } from "node:child_process";
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { robotStudies, robots, studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { trialOf } from "../support/trial-rows";

const SECRET = "robot-faults-test-secret".padEnd(40, "x");

const protocol = (robotId: string, actions: Array<[string, string, Record<string, unknown>]>): ProtocolSnapshot => ({
  schemaVersion: 5,
  experiment: { id: "e", name: "E", description: "", robotId },
  steps: actions.map(([id, type, parameters], i) => ({
    id: `s${i}`,
    name: `Step ${i}`,
    description: "",
    actions: [{ id, type, name: "", parameters, parallelGroup: null }],
  })),
});

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
mkdirSync(".tmp", { recursive: true });
const dir = resolve(mkdtempSync(join(".tmp", "robot-faults-")));
const sims: Simulator[] = [];
const sockets: TrialSocket[] = [];
let runtime: { url: string; child: ChildProcess };

/** A study with its wizard, one robot available to it, and one trial of `snapshot`: its socket, opened. */
async function studyWith(name: string, robot: typeof robots.$inferInsert, snapshot: ProtocolSnapshot) {
  const [study] = await db.insert(studies).values({ title: name, status: "active" }).returning();
  const wizard = await createAccount(db, {
    name: `Wizard of ${name}`,
    email: `${name.replace(/\W/g, "")}@example.org`,
    password: "password-123",
    role: "researcher",
  });
  await db.insert(studyMembers).values({ studyId: study!.id, userId: wizard.id, role: "wizard" });
  const [registered] = await db.insert(robots).values(robot).returning();
  await db.insert(robotStudies).values({ robotId: registered!.id, studyId: study!.id });
  const trialId = await trialOf(db, { studyId: study!.id, wizardId: wizard.id, snapshot, withParticipant: true });
  const socket = await connectTrial(runtime.url, signSocketToken({ userId: wizard.id, trialId }, SECRET));
  sockets.push(socket);
  return socket;
}

const spoken = (sim: Simulator) =>
  sim.received
    .filter((r) => r.message.op === "publish" && r.message.topic === "/speech")
    .map((r) => (r.message.msg as { data: string }).data);

const failures = (socket: TrialSocket) =>
  socket.messages.flatMap((m) =>
    m.type === "events"
      ? (m.events as Array<{ type: string; reason?: string }>).filter((e) => e.type === "action.failed")
      : [],
  );

beforeAll(async () => {
  sims.push(await startSimulator({ port: 0, nodes: simulatedRobot(firstPartyPlugin("simulated.json")) }));
  sims.push(await startSimulator({ port: 0, nodes: simulatedRobot(firstPartyPlugin("nao6-ros2.json")) }));
  writeFileSync(join(dir, "nao-b.key"), "this is the lab's wifi password, not a key\n");
  runtime = await startRuntime(url, SECRET);
  runtime.child.stderr!.on("data", (d) => process.stderr.write(`RT: ${d}`));
  runtime.child.stdout!.on("data", (d) => process.stderr.write(`RT: ${d}`));
}, 120_000);

afterAll(async () => {
  for (const s of sockets) s.close();
  runtime?.child.kill("SIGKILL");
  for (const sim of sims) await sim.close();
  await close();
  rmSync(dir, { recursive: true, force: true });
});

describe("a robot's faults stay in its trial", () => {
  it("an SSH action of a robot whose key file is not a key fails with that reason; another study's live trial goes on", {
    timeout: 90_000,
  }, async () => {
    const a = await studyWith(
      "Study A",
      { name: "Sim A", simulated: true, rosbridgeUrl: sims[0]!.url },
      protocol("simulated", [
        ["hi", "say", { text: "Hello from study A" }],
        ["bye", "say", { text: "Goodbye from study A" }],
      ]),
    );
    expect((await a.command("a1", { kind: "start" })).type).toBe("ack");
    expect((await a.command("a2", { kind: "next" })).type).toBe("ack");
    await expect.poll(() => spoken(sims[0]!)).toEqual(["Hello from study A"]);

    const b = await studyWith(
      "Study B",
      {
        name: "NAO B",
        pluginRobotId: "nao6-ros2",
        rosbridgeUrl: sims[1]!.url,
        sshHost: "127.0.0.1",
        sshPort: 22,
        sshUser: "nao",
        sshSecret: `file:${join(dir, "nao-b.key")}`,
      },
      protocol("nao6-ros2", [["wake", "nao6-ros2.wake_up", {}]]),
    );
    expect((await b.command("b1", { kind: "start" })).type).toBe("ack");
    expect((await b.command("b2", { kind: "next" })).type).toBe("ack");
    await expect.poll(() => failures(b), { timeout: 30_000 }).toHaveLength(1);
    expect(failures(b)[0]!.reason).toMatch(/the SSH key file \S+nao-b\.key does not hold a private key SSH can use/);
    expect(failures(b)[0]!.reason).not.toMatch(/\n|\bat .*:\d+:\d+|Error:/);

    // Study B's trial itself is still live, and study A's goes on as if nothing happened.
    expect((await b.command("b3", { kind: "note", text: "the robot's key is wrong" })).type).toBe("ack");
    expect((await a.command("a3", { kind: "next" })).type).toBe("ack");
    expect((await a.command("a4", { kind: "next" })).type).toBe("ack");
    await expect.poll(() => spoken(sims[0]!)).toEqual(["Hello from study A", "Goodbye from study A"]);
    expect(a.closed).toBeNull();
    expect(b.closed).toBeNull();
    expect(runtime.child.exitCode).toBeNull();
  });
});
