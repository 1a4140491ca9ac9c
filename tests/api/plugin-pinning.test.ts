// A published version pins the exact plugin document it was published
// against: its trials run with that document after the repository installs a
// newer one; a rehearsal runs with the robot's current plugin; a missing
// pinned document stops the trial from opening, with the reason.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { Plugin } from "../../src/core/plugins";
import { hashCanonical } from "../../src/core/protocol/canonical";
import { createSessionClient } from "../../src/store/client";
import { experimentVersions, pluginDocuments } from "../../src/store/schema";
import { trialPlugin } from "../../src/robots/trial-plugin";
import { unavailableRobot } from "../../src/runtime/robot-link";
import { trialHosts } from "../../src/runtime/trial-hosts";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const base = JSON.parse(
  readFileSync(join(import.meta.dirname, "..", "fixtures", "plugins", "base.json"), "utf8"),
) as Plugin;
const v1 = { ...base, robotId: "lab-bot", name: "Lab bot", version: "1.0.0" };
// The next release speaks on another topic: which one a trial uses shows which document it runs.
const v2 = {
  ...v1,
  version: "1.1.0",
  actions: v1.actions.map((a) => (a.id === "say_text" ? { ...a, ros2: { ...a.ros2!, topic: "/speech_v2" } } : a)),
} as Plugin;
const files: Record<string, string> = {
  "/repository.json": JSON.stringify({ id: "lab", name: "Our lab" }),
  "/plugins/index.json": JSON.stringify(["lab-bot.json"]),
  "/plugins/lab-bot.json": JSON.stringify(v1),
};

const { db, url, close } = await freshDatabase();
const f = await buildFixture(db);
const owner = f.api("owner");
let server: Server;

beforeAll(async () => {
  server = createServer((req, res) => (files[req.url!] ? res.end(files[req.url!]) : res.writeHead(404).end()));
  await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
  const repository = await f
    .api("admin")
    .plugins.repositories.add({ url: `http://127.0.0.1:${(server.address() as AddressInfo).port}/` });
  await f.api("admin").plugins.repositories.sync({ repositoryId: repository.id });
  repositoryId = repository.id;
  sync = () => f.api("admin").plugins.repositories.sync({ repositoryId });
});
afterAll(async () => {
  server?.close();
  await close();
});

let repositoryId = "";
let sync: () => Promise<unknown>;
const topicOf = (plugin: Plugin | null) =>
  (plugin?.actions.find((a) => a.id === "say_text")?.ros2 as { topic: string } | undefined)?.topic;

describe("a published version pins its plugin document", async () => {
  const study = await f.newStudy();
  const experiment = await owner.experiments.create({ studyId: study.id, name: "Greeting", robotId: "lab-bot" });
  await owner.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "Hello", actions: [{ type: "lab-bot.say_text", parameters: { text: "Hello" } }] }],
  });
  let version: Awaited<ReturnType<typeof owner.versions.publish>>;
  let trialId = "";

  it("records the hash of the document it was published against, in versions.list and versions.get", async () => {
    version = await owner.versions.publish({ experimentId: experiment.id });
    const hash = hashCanonical(v1);
    expect(version.pluginHash).toBe(hash);
    expect((await owner.versions.list({ experimentId: experiment.id }))[0]).toMatchObject({
      robotId: "lab-bot",
      pluginVersion: "1.0.0",
      pluginHash: hash,
    });
    expect(await owner.versions.get({ versionId: version.id })).toMatchObject({ pluginHash: hash });
    const [stored] = await db.select().from(pluginDocuments).where(eq(pluginDocuments.hash, hash));
    expect(stored).toMatchObject({ robotId: "lab-bot", version: "1.0.0", source: repositoryId, definition: v1 });
  });

  it("runs its trials with that document after the repository installs a newer one; a rehearsal runs the newer", async () => {
    trialId = (await owner.trials.create({ versionId: version.id })).id;
    files["/plugins/lab-bot.json"] = JSON.stringify(v2);
    await sync();
    expect((await f.api("observer").plugins.get({ robotId: "lab-bot" })).version).toBe("1.1.0");
    const pinned = await trialPlugin(db, trialId);
    expect(pinned).toMatchObject({
      ok: true,
      robotId: "lab-bot",
      pinnedHash: hashCanonical(v1),
      plugin: { version: "1.0.0" },
    });
    expect(topicOf(pinned.ok ? pinned.plugin : null)).toBe("/speech");
    const rehearsal = await owner.trials.rehearse({ experimentId: experiment.id });
    const current = await trialPlugin(db, rehearsal.id);
    expect(current).toMatchObject({ ok: true, pinnedHash: null, plugin: { version: "1.1.0" } });
    expect(topicOf(current.ok ? current.plugin : null)).toBe("/speech_v2");
  });

  it("opens the trial in the runtime with exactly the pinned document", async () => {
    const given: Array<Plugin | null> = [];
    const hosts = trialHosts(
      db,
      () => createSessionClient(url),
      (plugin, robotId) => (given.push(plugin), unavailableRobot(`test robot for ${robotId}`)),
      () => {},
    );
    try {
      expect(await hosts.get(trialId)).not.toBeNull();
      expect(given.map((p) => [p?.version, topicOf(p)])).toEqual([["1.0.0", "/speech"]]);
    } finally {
      await hosts.closeAll();
    }
  });

  it("falls back to the current plugin for a version published before pinning", async () => {
    const legacy = await owner.versions.publish({ experimentId: experiment.id });
    await db.update(experimentVersions).set({ pluginHash: null }).where(eq(experimentVersions.id, legacy.id));
    const trial = await owner.trials.create({ versionId: legacy.id });
    expect(await trialPlugin(db, trial.id)).toMatchObject({ ok: true, pinnedHash: null, plugin: { version: "1.1.0" } });
  });

  it("refuses to open a trial whose pinned document is missing, and says why", async () => {
    await db.delete(pluginDocuments).where(eq(pluginDocuments.hash, hashCanonical(v1)));
    const reason = `Version 1 was published with a lab-bot plugin document (${hashCanonical(v1).slice(0, 12)}) that is no longer stored, so its trials cannot run. Publish the experiment again to run it with the plugin installed now.`;
    expect(await trialPlugin(db, trialId)).toEqual({ ok: false, reason });
    const hosts = trialHosts(
      db,
      () => createSessionClient(url),
      () => unavailableRobot("never asked"),
      () => {},
    );
    try {
      const other = await owner.trials.create({ versionId: version.id });
      await expect(hosts.get(other.id)).rejects.toThrow(reason);
    } finally {
      await hosts.closeAll();
    }
  });

  it("refuses to start a trial on a robot whose plugin lacks an action of the version, naming each", async () => {
    // A version published before pinning runs with the plugin installed now, which has dropped say_text.
    const legacy = await owner.versions.publish({ experimentId: experiment.id });
    await db.update(experimentVersions).set({ pluginHash: null }).where(eq(experimentVersions.id, legacy.id));
    files["/plugins/lab-bot.json"] = JSON.stringify({
      ...v2,
      version: "1.2.0",
      abstract: {},
      actions: v2.actions.filter((a) => a.id !== "say_text"),
    });
    await sync();
    const trial = await owner.trials.create({ versionId: legacy.id });
    const hosts = trialHosts(
      db,
      () => createSessionClient(url),
      () => unavailableRobot("never asked"),
      () => {},
    );
    try {
      await expect(hosts.get(trial.id)).rejects.toThrow(
        'This trial cannot start: Lab bot (plugin 1.2.0) cannot do an action of its protocol: step 1 (Hello), "lab-bot.say_text": lab-bot has no action "say_text".',
      );
    } finally {
      await hosts.closeAll();
    }
  });
});
