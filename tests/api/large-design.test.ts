// The largest design the limits allow (100 steps of 500 actions, 1.8 MB as a
// file) is imported, saved, published and run like a small one: a trial of
// it starts in the real runtime, which loads its whole protocol. A design
// over a limit is refused before any work, the limit named.
import { readFileSync } from "node:fs";
import type { ChildProcess } from "node:child_process";
import { TRPCError } from "@trpc/server";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { freshDatabase } from "../support/db";
import { largeExperimentFile, largeSteps } from "../support/large-design";
import { startRuntime } from "../support/runtime";
import { connectTrial } from "../support/socket";
import { buildFixture, TEST_SECRET } from "./fixture";

const nao = (() => {
  const loaded = loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8"));
  if (!loaded.ok) throw new Error("plugins/nao6-ros2.json does not load");
  return loaded.value as Plugin;
})();

const { db, url, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
let sim: Simulator;
let runtime: { url: string; child: ChildProcess };

beforeAll(async () => {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { msPerChar: 0 }) });
  runtime = await startRuntime(url, TEST_SECRET, { HRI_ROSBRIDGE_URL: sim.url, HRI_SIMULATOR_URL: sim.url });
});
afterAll(async () => {
  runtime?.child.kill("SIGKILL");
  await sim?.close();
  await close();
});

const shape = (design: { steps: Array<{ name: string; actions: Array<{ name: string }> }> }) =>
  design.steps.map((s) => [s.name, s.actions.length, s.actions.at(-1)!.name]);

describe("a design of 100 steps of 500 actions", () => {
  it("is imported, saved, published, and a trial of it starts in the runtime", async () => {
    const study = await f.newStudy();
    const { id } = await owner.experiments.importFile({ studyId: study.id, text: largeExperimentFile(100, 500) });
    const imported = await owner.experiments.get({ experimentId: id });
    expect(shape(imported)).toEqual(shape({ steps: largeSteps(100, 500) }));

    // Saved again with its ids, the last step's actions in reverse.
    const steps = imported.steps.map((s, i) => ({
      id: s.id,
      name: s.name,
      actions: (i === 99 ? [...s.actions].reverse() : s.actions).map((a) => ({ id: a.id, type: a.type, name: a.name })),
    }));
    const saved = await owner.experiments.saveDesign({
      experimentId: imported.id,
      baseRevision: imported.draftRevision,
      steps,
    });
    expect(saved.steps.flatMap((s) => s.actions.map((a) => a.id))).toEqual(
      steps.flatMap((s) => s.actions.map((a) => a.id)),
    );

    const version = await owner.versions.publish({ experimentId: imported.id });
    const trial = await owner.trials.create({ versionId: version.id });
    const { token } = await owner.trials.socketToken({ trialId: trial.id });
    const wizard = await connectTrial(runtime.url, token);
    try {
      expect(await wizard.command("start", { kind: "start" })).toMatchObject({ type: "ack" });
      expect(await wizard.command("next", { kind: "next" })).toMatchObject({ type: "ack" });
      // The first wave of the first step reaches the robot: the runtime holds the whole protocol.
      const first = saved.steps[0]!.actions[0]!.id;
      await wizard.next((m) => JSON.stringify(m).includes(`"action.completed"`) && JSON.stringify(m).includes(first));
    } finally {
      wizard.close();
    }
  }, 120_000);
});

describe("a design over a limit", () => {
  const refusal = (promise: Promise<unknown>) =>
    promise.then(
      () => null,
      (e: unknown) => e as TRPCError,
    );

  it("is refused on import with the limit named", async () => {
    const study = await f.newStudy();
    const error = await refusal(
      owner.experiments.importFile({ studyId: study.id, text: largeExperimentFile(101, 500).replaceAll("Wave ", "") }),
    );
    expect(error).toBeInstanceOf(TRPCError);
    expect(error!.message).toContain("The design has 50,500 actions; the limit is 50,000");
  });

  it("is refused on save with the limit named, and the draft is unchanged", async () => {
    const study = await f.newStudy();
    const experiment = await owner.experiments.create({ studyId: study.id, name: "Too large", robotId: "nao6-ros2" });
    const error = await refusal(
      owner.experiments.saveDesign({ experimentId: experiment.id, baseRevision: 0, steps: largeSteps(101, 500) }),
    );
    expect(error).toBeInstanceOf(TRPCError);
    expect(error!.message).toContain("The design has 50,500 actions; the limit is 50,000");
    expect((await owner.experiments.get({ experimentId: experiment.id })).steps).toEqual([]);
  });
});
