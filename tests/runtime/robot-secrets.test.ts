// A robot record saved before robot secrets had their own variables may name
// any variable as its SSH password, the platform's own included. Through the
// real runtime process, PostgreSQL and the simulated NAO6: such a record is
// refused at the trial's start in plain words that name the variable and
// where robot secrets go, and nothing at all is sent: not to the robot's
// rosbridge, not to its SSH address (a listener that counts who knocks).
import { createServer, type Server } from "node:net";
import { afterAll, beforeAll, expect, it } from "vitest";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { freePort } from "../../src/store/embedded";
import { experimentVersions, experiments, robots, studies, studyMembers, trials } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { firstPartyPlugin } from "../support/plugins";
import { oneStep } from "../support/protocols";

const SECRET = "robot-secrets-test-secret".padEnd(40, "x");
const nao = firstPartyPlugin("nao6-ros2.json");
const REFUSED =
  'The SSH secret of "NAO by the door" refers to BETTER_AUTH_SECRET, which is not a robot secret; name a variable starting HRI_ROBOT_SECRET_.';

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 2 });
let sim: Simulator;
let sshd: Server;
let knocks = 0;
let runtime: Awaited<ReturnType<typeof startRuntime>>;
let wizard: TrialSocket;

beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { msPerChar: 0 }) });
  const sshPort = await freePort();
  sshd = createServer((socket) => {
    knocks++;
    socket.destroy();
  });
  await new Promise<void>((ok) => sshd.listen(sshPort, "127.0.0.1", ok));
  const [study] = await db.insert(studies).values({ title: "Door study", status: "active" }).returning();
  const wizardId = (
    await createAccount(db, {
      name: "W",
      email: "w@robot-secrets.example.org",
      password: "password-123",
      role: "researcher",
    })
  ).id;
  await db.insert(studyMembers).values({ studyId: study!.id, userId: wizardId, role: "wizard" });
  // As an older release let an administrator save it: the password "by reference" to the platform's own secret.
  await db.insert(robots).values({
    name: "NAO by the door",
    rosbridgeUrl: sim.url,
    sshHost: "127.0.0.1",
    sshPort,
    sshUser: "nao",
    sshSecret: "env:BETTER_AUTH_SECRET",
    allStudies: true,
  });
  const [experiment] = await db
    .insert(experiments)
    .values({ studyId: study!.id, name: "Greeting", robotId: "nao6-ros2" })
    .returning();
  const snapshot = oneStep([
    { id: "hi", type: "say", parameters: { text: "Hello" } },
    { id: "up", type: "nao6-ros2.wake_up" },
  ]);
  const [version] = await db
    .insert(experimentVersions)
    .values({ experimentId: experiment!.id, version: 1, snapshot, hash: "door", robotId: "nao6-ros2" })
    .returning();
  const [trial] = await db
    .insert(trials)
    .values({ studyId: study!.id, experimentId: experiment!.id, versionId: version!.id, wizardId })
    .returning();
  runtime = await startRuntime(url, SECRET);
  wizard = await connectTrial(runtime.url, signSocketToken({ userId: wizardId, trialId: trial!.id }, SECRET));
}, 120_000);

afterAll(async () => {
  wizard?.close();
  runtime?.child.kill("SIGKILL");
  await sim?.close();
  await new Promise((ok) => sshd?.close(ok));
  await close();
});

it("refuses to start a trial on a robot whose password names the platform's secret, and sends the robot nothing", async () => {
  expect(await wizard.next((m) => m.type === "robot" && m.detail === REFUSED)).toMatchObject({ connected: false });
  expect(await wizard.command("s", { kind: "start" })).toEqual({ type: "rejected", requestId: "s", reason: REFUSED });
  // Asked again (a wizard who tries twice): the same words, and still nothing sent.
  expect(await wizard.command("t", { kind: "start" })).toMatchObject({ reason: REFUSED });
  expect(sim.received).toEqual([]);
  expect(knocks).toBe(0);
});
