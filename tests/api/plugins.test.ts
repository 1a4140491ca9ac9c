// The robots the server offers come through the public plugin loader; a
// published version records the plugin version; portability is reported
// before any trial, per robot, for the seeded Interactive Storyteller.
import { afterAll, describe, expect, it } from "vitest";
import { cannotStart, portability } from "../../src/core/plugins";
import { seedDemo } from "../../src/server/seed/demo";
import { freshDatabase } from "../support/db";
import { buildFixture, demoPerson } from "./fixture";

const { db, close } = await freshDatabase();
await seedDemo(db);
const f = await buildFixture(db);
afterAll(close);

/** The demo study's owner, as the seed made them. */
const demoOwner = async () => f.apiAs(await demoPerson(db, "researcher@demo.hristudio"));

describe("robot plugins on the server", () => {
  it("lists the first-party robots with their versions", async () => {
    const { robots, problems } = await f.api("observer").plugins.list();
    expect(robots.map((r) => r.robotId).sort()).toEqual(["nao6-ros2", "pepper-ros2", "simulated", "turtlebot3-burger"]);
    expect(robots.find((r) => r.robotId === "nao6-ros2")!.version).toBe("3.0.0");
    expect(problems).toEqual([]);
  });

  it("removes a repository from the list, and adding it again brings it back with the trust chosen then", async () => {
    const admin = f.api("admin");
    const url = `http://127.0.0.1:9/${crypto.randomUUID()}/`;
    const added = await admin.plugins.repositories.add({ url, trust: "community" });
    await admin.plugins.repositories.remove({ repositoryId: added.id });
    expect((await admin.plugins.repositories.list()).map((r) => r.url)).not.toContain(url);
    const again = await admin.plugins.repositories.add({ url, trust: "verified" });
    expect(again).toMatchObject({ id: added.id, trust: "verified", enabled: true });
    await expect(admin.plugins.repositories.add({ url })).rejects.toMatchObject({ code: "CONFLICT" });
  });

  it("records the exact plugin version in a published version", async () => {
    const study = await f.newStudy();
    const e = await f.api("owner").experiments.create({ studyId: study.id, name: "E", robotId: "nao6-ros2" });
    await f.api("owner").experiments.saveDesign({
      experimentId: e.id,
      baseRevision: 0,
      steps: [{ name: "S", actions: [{ type: "wave" }] }],
    });
    expect(await f.api("owner").versions.publish({ experimentId: e.id })).toMatchObject({
      robotId: "nao6-ros2",
      pluginVersion: "3.0.0",
    });
  });

  it("reports the Storyteller's portability per robot before any trial", async () => {
    const asOwner = await demoOwner();
    const [study] = await asOwner.studies.mine();
    const [storyteller] = await asOwner.experiments.list({ studyId: study!.id });
    // As the designer does: the draft and the robot's plugin from the server, the report from the core.
    const draft = await asOwner.experiments.get({ experimentId: storyteller!.id });
    const unsupported = async (robotId: string) =>
      portability(draft, await asOwner.plugins.get({ robotId }))
        .actions.filter((a) => a.status !== "supported")
        .map((a) => a.type)
        .sort();
    expect(await unsupported("nao6-ros2")).toEqual([]);
    expect(await unsupported("simulated")).toEqual([]);
    expect(await unsupported("turtlebot3-burger")).toEqual([
      "head_shake",
      "look_down",
      "nod",
      "say",
      "say",
      "say",
      "say",
      "say",
      "wave",
    ]);
    await expect(asOwner.plugins.get({ robotId: "r2d2" })).rejects.toThrow(
      'No robot plugin called "r2d2" is installed.',
    );
  });

  it.each([
    ["nao6-ros2", null],
    ["pepper-ros2", null],
    ["simulated", null],
    ["turtlebot3-burger", 9],
  ] as const)(
    "publishes the Storyteller on %s only if the robot can do every action, listing each it cannot",
    async (robotId, refused) => {
      const asOwner = await demoOwner();
      const [study] = await asOwner.studies.mine();
      const [storyteller] = await asOwner.experiments.list({ studyId: study!.id });
      const copy = await asOwner.experiments.duplicate({ experimentId: storyteller!.id });
      const draft = await asOwner.experiments.get({ experimentId: copy.id });
      await asOwner.experiments.saveDesign({
        experimentId: copy.id,
        baseRevision: draft.draftRevision,
        details: { robotId },
        steps: draft.steps,
      });
      const publishing = asOwner.versions.publish({ experimentId: copy.id });
      if (refused === null) return expect((await publishing).robotId).toBe(robotId);
      const error = await publishing.then(
        () => null,
        (e: Error) => e.message,
      );
      expect(error).toMatch(
        new RegExp(
          `^This experiment cannot be published: TurtleBot3 Burger cannot do these ${refused} actions\\. Step 1 \\(`,
        ),
      );
      expect(error!.match(/cannot run on TurtleBot3 Burger: /g)).toHaveLength(refused);
      expect(error).toContain("cannot run on TurtleBot3 Burger: The TurtleBot3 has no speaker");
      expect(error).toMatch(/Replace or remove them, or choose another robot\.$/);
      expect(await asOwner.versions.list({ experimentId: copy.id })).toEqual([]);
    },
  );

  it.each([
    ["nao6-ros2", 0],
    ["pepper-ros2", 0],
    ["simulated", 0],
    ["turtlebot3-burger", 9],
  ] as const)(
    "a trial of the Storyteller cannot start on %s if its plugin lacks an action, each named",
    async (robotId, missing) => {
      const asOwner = await demoOwner();
      const [study] = await asOwner.studies.mine();
      // The Storyteller published for the NAO6, as the seed designs it.
      const [storyteller] = await asOwner.experiments.list({ studyId: study!.id });
      const copy = await asOwner.experiments.duplicate({ experimentId: storyteller!.id });
      const published = await asOwner.versions.publish({ experimentId: copy.id });
      expect(published.robotId).toBe("nao6-ros2");
      const version = await asOwner.versions.get({ versionId: published.id });
      const reason = cannotStart(version.snapshot, await asOwner.plugins.get({ robotId }));
      if (!missing) return expect(reason).toBeNull();
      expect(reason).toMatch(
        new RegExp(
          `^This trial cannot start: TurtleBot3 Burger \\(plugin [0-9.]+\\) cannot do ${missing} actions of its protocol: step 1 `,
        ),
      );
      expect(reason!.match(/; step /g)).toHaveLength(missing - 1);
    },
  );
});
