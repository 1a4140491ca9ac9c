// A trial open in a runtime claims its robot (an advisory lock on a session
// of its own). When that session ends and another process takes the robot's
// claim meanwhile, the runtime acts on it: the trial's host closes, with its
// link to the robot, and the wizard is told the robot is driven elsewhere.
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { ProtocolSnapshot } from "../../src/core/protocol/document";
import { robotClaimed } from "../../src/core/robots/registry";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { createAccount } from "../../src/server/auth/accounts";
import { pluginRobot } from "../../src/runtime/robot-link";
import { trialHosts, type TrialHosts } from "../../src/runtime/trial-hosts";
import { createSessionClient } from "../../src/store/client";
import { robotStudies, robots, studies } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { trialOf } from "../support/trial-rows";

const plugin = firstPartyPlugin("simulated.json");
const snapshot: ProtocolSnapshot = {
  schemaVersion: 5,
  experiment: { id: "e", name: "Claimed", description: "", robotId: "simulated" },
  steps: [
    {
      id: "s1",
      name: "Greeting",
      description: "",
      actions: [{ id: "hi", type: "say", name: "", parameters: { text: "Hi" }, parallelGroup: null }],
    },
  ],
};

const { db, sql, url, close } = await freshDatabase();
let sim: Simulator;
let hosts: TrialHosts;
const told: Array<{ trialId: string; connected: boolean; detail?: string }> = [];
/** Another process's lock session. */
const rival = createSessionClient(url);

beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(plugin, { msPerChar: 0 }) });
  hosts = trialHosts(
    db,
    (closed) => createSessionClient(url, closed),
    () => pluginRobot(plugin, new RosbridgeTransport({ url: sim.url })),
    (trialId, connected, detail) => told.push({ trialId, connected, detail }),
  );
});
afterAll(async () => {
  await hosts.closeAll();
  await rival.end();
  await sim.close();
  await close();
});

describe("a robot claim lost", () => {
  it("closes the trial open on the robot and tells its wizard, once another process took the robot", async () => {
    const [study] = await db.insert(studies).values({ title: "Claims", status: "active" }).returning();
    const wizard = await createAccount(db, {
      name: "Wizard",
      email: "w@example.org",
      password: "password-123",
      role: "researcher",
    });
    const [robot] = await db.insert(robots).values({ name: "Sim", simulated: true, rosbridgeUrl: sim.url }).returning();
    await db.insert(robotStudies).values({ robotId: robot!.id, studyId: study!.id });
    const trialId = await trialOf(db, { studyId: study!.id, wizardId: wizard.id, snapshot });
    const host = await hosts.get(trialId);
    expect(host).not.toBeNull();
    await expect.poll(() => sim.connections()).toBe(1);

    const key = `robot:${robot!.id}`;
    const [claim] = await sql<[{ pid: number }]>`
      select pid from pg_locks where locktype = 'advisory' and granted
        and ((classid::bigint << 32) | objid::bigint) = hashtextextended(${key}, 0)`;
    // The other process waits for the robot, so it has it the moment the claim's session ends.
    const waiting = rival`select pg_advisory_lock(hashtextextended(${key}, 0))`.execute();
    await expect
      .poll(async () => (await sql`select 1 from pg_locks where locktype = 'advisory' and not granted`).length)
      .toBe(1);
    await sql`select pg_terminate_backend(${claim!.pid})`;
    await waiting;

    await expect
      .poll(() => told.filter((t) => t.trialId === trialId && !t.connected).map((t) => t.detail))
      .toContain(robotClaimed("Sim", "elsewhere"));
    await expect.poll(() => [hosts.size, sim.connections(), host!.closed]).toEqual([0, 0, true]);
  });
});
