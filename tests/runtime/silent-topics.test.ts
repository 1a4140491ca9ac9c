// A declared state topic the robot never publishes, through the real runtime
// process: the simulated NAO6 is started without its battery node, so the
// plugin's /battery never speaks (as on a ROS 1 bridge refusing its ROS 2
// type name, nothing says why on the wire). The wizard's socket is told, in
// plain words, beside "robot connected", and the trial's log has it.
import type { ChildProcess } from "node:child_process";
import { afterAll, beforeAll, expect, it } from "vitest";
import {
  camera,
  jointStates,
  pluginTopics,
  robotStateReport,
  speech,
  startSimulator,
  type Simulator,
} from "../../src/robots/simulator";
import { createAccount } from "../../src/server/auth/accounts";
import { createDatabase } from "../../src/store/client";
import { studies, studyMembers } from "../../src/store/schema";
import { signSocketToken } from "../../src/store/socket-token";
import { freshDatabaseUrl } from "../support/db";
import { firstPartyPlugin } from "../support/plugins";
import { startRuntime } from "../support/runtime";
import { connectTrial, type TrialSocket } from "../support/socket";
import { naoTrialOf } from "../support/trial-rows";

const SECRET = "silent-topics-test-secret".padEnd(40, "x");
const SILENT =
  "The robot never sent /battery (expected about every 1 s; nothing in 5 s): the usual causes are a ROS 1 bridge, which refuses the ROS 2 type name sensor_msgs/msg/BatteryState without telling us (it names it sensor_msgs/BatteryState), or nothing on the robot publishing /battery.";

const url = await freshDatabaseUrl();
const { db, close } = createDatabase(url, { max: 4 });
let sim: Simulator;
let socket: TrialSocket | null = null;
let runtime: { url: string; child: ChildProcess };

beforeAll(async () => {
  const nao = firstPartyPlugin("nao6-ros2.json");
  sim = await startSimulator({
    port: 0,
    // Every state topic the plugin declares but /battery: the camera too, which the runtime may subscribe.
    nodes: [
      pluginTopics(nao),
      speech({ msPerChar: 1 }),
      jointStates({ hz: 10 }),
      robotStateReport(),
      camera({ hz: 5 }),
    ],
  });
  runtime = await startRuntime(url, SECRET);
}, 120_000);

afterAll(async () => {
  socket?.close();
  runtime?.child.kill("SIGKILL");
  await sim?.close();
  await close();
});

it("a state topic the robot never publishes is told to the wizard in plain words, and logged", {
  timeout: 60_000,
}, async () => {
  const [study] = await db.insert(studies).values({ title: "Silent", status: "active" }).returning();
  const wizard = await createAccount(db, {
    name: "Wizard",
    email: "wizard-silent@example.org",
    password: "password-123",
    role: "researcher",
  });
  await db.insert(studyMembers).values({ studyId: study!.id, userId: wizard.id, role: "wizard" });
  const trialId = await naoTrialOf(db, {
    studyId: study!.id,
    wizardId: wizard.id,
    rosbridgeUrl: sim.url,
    robotName: "NAO without a battery report",
  });
  socket = await connectTrial(runtime.url, signSocketToken({ userId: wizard.id, trialId }, SECRET));
  expect((await socket.command("c1", { kind: "start" })).type).toBe("ack");

  // What the wizard's page shows as "robot connected (…)": the link is up, the topic is not.
  const told = await socket.next((m) => m.type === "robot" && m.detail === SILENT, 30_000);
  expect(told).toMatchObject({ connected: true });
  const logged = () =>
    socket!.messages.flatMap((m) =>
      m.type === "events"
        ? (m.events as Array<{ type: string; text?: string }>).filter((e) => e.type === "robot.problem")
        : [],
    );
  await expect.poll(logged, { timeout: 10_000 }).toEqual([expect.objectContaining({ text: SILENT })]);
  // The topics it does publish are not named.
  expect(socket.messages.filter((m) => m.type === "robot" && m.detail && m.detail !== SILENT)).toEqual([]);
});
