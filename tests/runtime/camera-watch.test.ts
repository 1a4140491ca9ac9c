// The robot's camera goes only to pages that show it, through the real
// runtime process and the simulated NAO6 over rosbridge: a page that says it
// does not (a hidden tab, a closed panel) gets no frames from its answer on,
// the others still do; when no page of the trial shows it, the runtime
// unsubscribes from the robot's camera, and subscribes again when one does.
import type { ChildProcess } from "node:child_process";
import { afterAll, beforeAll, expect, it } from "vitest";
import { CAMERA_TOPIC, simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { naoTrialOf } from "../support/trial-rows";

const SECRET = "camera-watch-test-secret".padEnd(40, "x");

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
let sim: Simulator;
let runtime: { url: string; child: ChildProcess };
const sockets: TrialSocket[] = [];

beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(firstPartyPlugin("nao6-ros2.json"), { msPerChar: 0 }) });
  runtime = await startRuntime(url, SECRET);
}, 120_000);

afterAll(async () => {
  for (const s of sockets) s.close();
  runtime?.child.kill("SIGKILL");
  await sim?.close();
  await close();
});

const frames = (s: TrialSocket) => s.messages.filter((m) => m.type === "camera").length;
/** Resolves once this socket has received `more` frames from now; fails after 10 s without them. */
const moreFrames = (s: TrialSocket, more: number) => {
  const from = frames(s);
  return s.next(() => frames(s) >= from + more, 10_000);
};
/** The robot's camera subscriptions and unsubscriptions, as the robot received them. */
const cameraOps = () =>
  sim.received
    .map((r) => r.message as { op?: string; topic?: string })
    .filter((m) => m.topic === CAMERA_TOPIC && (m.op === "subscribe" || m.op === "unsubscribe"))
    .map((m) => m.op);

it("sends the robot's camera only to the pages that show it, and asks the robot for it only while one does", {
  timeout: 60_000,
}, async () => {
  const [study] = await db.insert(studies).values({ title: "Camera", status: "active" }).returning();
  const person = async (name: string, role: "wizard" | "observer") => {
    const account = await createAccount(db, {
      name,
      email: `${role}-camera@example.org`,
      password: "password-123",
      role: "researcher",
    });
    await db.insert(studyMembers).values({ studyId: study!.id, userId: account.id, role });
    return account.id;
  };
  const wizardId = await person("Wizard", "wizard");
  const observerId = await person("Observer", "observer");
  const trialId = await naoTrialOf(db, {
    studyId: study!.id,
    wizardId,
    rosbridgeUrl: sim.url,
    robotName: "NAO",
  });
  const open = async (userId: string) => {
    const socket = await connectTrial(runtime.url, signSocketToken({ userId, trialId }, SECRET));
    sockets.push(socket);
    return socket;
  };
  const wizard = await open(wizardId);
  expect((await wizard.command("start", { kind: "start" })).type).toBe("ack");
  const observer = await open(observerId);
  // A page that never says gets the camera, as every page did before it could say.
  await Promise.all([moreFrames(wizard, 2), moreFrames(observer, 2)]);
  const say = async (s: TrialSocket, requestId: string, watch: boolean) => {
    s.send({ type: "camera", requestId, watch });
    return s.next((m) => m.requestId === requestId);
  };

  // The observer hides it: from its answer on, no frame, while the wizard's keep coming.
  expect(await say(observer, "hide", false)).toMatchObject({ type: "ack" });
  const hiddenAt = frames(observer);
  await moreFrames(wizard, 4);
  expect(frames(observer)).toBe(hiddenAt);
  expect(cameraOps()).toEqual(["subscribe"]);

  // The wizard too: nobody shows it, so the robot is asked to stop sending it.
  expect(await say(wizard, "hide-too", false)).toMatchObject({ type: "ack" });
  await expect.poll(cameraOps, { timeout: 10_000 }).toEqual(["subscribe", "unsubscribe"]);
  const wizardAt = frames(wizard);

  // The observer shows it again: the robot is asked again, and frames come to the observer alone.
  expect(await say(observer, "show", true)).toMatchObject({ type: "ack" });
  await moreFrames(observer, 3);
  expect(cameraOps()).toEqual(["subscribe", "unsubscribe", "subscribe"]);
  expect(frames(wizard)).toBe(wizardAt);
  // Said twice, it is still one watcher: hiding once stops it.
  expect(await say(observer, "show-again", true)).toMatchObject({ type: "ack" });
  expect(await say(observer, "hide-again", false)).toMatchObject({ type: "ack" });
  await expect.poll(cameraOps, { timeout: 10_000 }).toEqual(["subscribe", "unsubscribe", "subscribe", "unsubscribe"]);
});
