// Ctrl+C in the terminal `npm start` runs in: every process stops quietly (no
// stack trace, no database error), the robot samples the runtime still held
// are stored, the launcher exits with 0 and forgets the children it had.
import { existsSync } from "node:fs";
import { join } from "node:path";
import postgres from "postgres";
import * as ROSLIB from "roslib";
import { afterAll, describe, expect, it } from "vitest";
import { startEmbeddedPostgres } from "../../src/store/embedded";
import { DEMO_PASSWORD, startApp, type RunningApp } from "../support/app";
import { apiClient, signIn } from "../support/http";
import { connectTrial } from "../support/socket";

type Stamp = { sec: number; nanosec: number };
const ns = (s: Stamp) => BigInt(s.sec) * 1_000_000_000n + BigInt(s.nanosec);

/** Hears every joint state the simulated robot publishes (the runtime's throttle may skip one now and then). */
async function hearJointStates(url: string) {
  const ros = new ROSLIB.Ros({ url });
  await new Promise<void>((ok, fail) => {
    ros.on("connection", () => ok());
    ros.on("error", (e) => fail(new Error(`Could not reach the simulated robot at ${url}: ${String(e)}`)));
  });
  const heard: bigint[] = [];
  const topic = new ROSLIB.Topic<{ header: { stamp: Stamp } }>({
    ros,
    name: "/joint_states",
    messageType: "sensor_msgs/msg/JointState",
  });
  topic.subscribe((m) => heard.push(ns(m.header.stamp)));
  return { heard, close: () => ros.close() };
}

describe("Ctrl+C", () => {
  let app: RunningApp | undefined;
  afterAll(async () => app?.stop());

  it("stops every process quietly, keeps the last robot samples and forgets its children", {
    timeout: 240_000,
  }, async () => {
    app = await startApp({ npmStart: true });
    const researcher = apiClient(app.url, await signIn(app.url, "researcher@demo.hristudio", DEMO_PASSWORD));
    const wizardApi = apiClient(app.url, await signIn(app.url, "wizard@demo.hristudio", DEMO_PASSWORD));
    const [study] = await researcher.studies.mine.query();
    const [experiment] = await researcher.experiments.list.query({ studyId: study!.id });
    const version = await researcher.versions.publish.mutate({ experimentId: experiment!.id });
    const [participant] = await researcher.participants.list.query({ studyId: study!.id });
    const trialId = (await wizardApi.trials.create.mutate({ versionId: version.id, participantId: participant!.id }))
      .id;
    const { url, token } = await wizardApi.trials.socketToken.mutate({ trialId });
    const wizard = await connectTrial(url, token, 0);
    const robot = await hearJointStates(app.simulatorUrl);
    expect(await wizard.command("r1", { kind: "start" })).toMatchObject({ type: "ack" });

    // Right after a batch was stored (the count grew), and three more heard: those are still in the
    // runtime's hands, for the next batch, when Ctrl+C comes.
    const stored = async () => (await researcher.trials.samples.query({ trialId, topic: "/joint_states" })).length;
    const before = await stored();
    await expect.poll(stored, { timeout: 30_000, interval: 20 }).not.toBe(before);
    const heardAtBatch = robot.heard.length;
    await expect.poll(() => robot.heard.length).toBeGreaterThanOrEqual(heardAtBatch + 3);
    const heard = [...robot.heard];
    const erredBefore = app.errors().length;
    await app.interrupt();
    robot.close();
    wizard.close();

    expect(app.process.exitCode).toBe(0);
    // Not a word on stderr while stopping: no stack trace, no database error, no robot reported lost.
    expect(app.errors().slice(erredBefore)).toBe("");
    expect(existsSync(join(app.dataDir, "launcher-children.json"))).toBe(false);

    // The runtime had the robot's state of the last moments before the stop (its throttle may have
    // skipped one of two in a row, and the very last may not have reached it yet): it is stored.
    const database = await startEmbeddedPostgres({ dataDir: app.dataDir });
    const sql = postgres(database.url, { max: 1, onnotice: () => {} });
    try {
      const rows = await sql<{ stamp: Stamp }[]>`
        select data->'header'->'stamp' as stamp from trial_samples where trial_id = ${trialId} and topic = '/joint_states'`;
      const latest = rows.map((r) => ns(r.stamp)).reduce((a, b) => (a > b ? a : b), 0n);
      expect(latest).toBeGreaterThanOrEqual(heard.at(-3)!);
    } finally {
      await sql.end();
      await database.stop();
    }
  });
});
