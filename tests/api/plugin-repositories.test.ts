// An administrator adds a plugin repository with the trust they choose; sync
// fetches it over real HTTP, keeps the good plugins (the HRIStudio fixture
// unmodified), refuses the bad one with file, path and reason, keeps a robot
// another source also provides beside it (told apart by source and hash, said
// so in the report, never the default in its place), and reports what changed.
// An experiment chooses which document of its robot it runs, and its trials run that one.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { and, eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { Plugin } from "../../src/core/plugins";
import { hashCanonical } from "../../src/core/protocol/canonical";
import { trialPlugin } from "../../src/robots/trial-plugin";
import { auditLog } from "../../src/store/schema";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const FIXTURE = join(import.meta.dirname, "..", "fixtures", "hristudio-plugins");
const repositoryJson = readFileSync(join(FIXTURE, "repository.json"), "utf8");
const nao = JSON.parse(readFileSync(join(FIXTURE, "plugins", "nao6-ros2.json"), "utf8"));
const lab = { ...nao, robotId: "nao6-lab", name: "NAO6 (our lab)", version: "1.0.0", trustLevel: "official" };
const json = (value: unknown) => JSON.stringify(value);

// Every repository below says it is official in its own repository.json.
const files: Record<string, string> = {
  "/first/repository.json": repositoryJson,
  "/first/plugins/nao6-ros2.json": readFileSync(join(FIXTURE, "plugins", "nao6-ros2.json"), "utf8"),
  "/first/plugins/index.json": json(["nao6-ros2.json", "nao6-lab.json", "broken.json"]),
  "/first/plugins/nao6-lab.json": json(lab),
  "/first/plugins/broken.json": json({ ...nao, robotId: "broken", actions: [{ ...nao.actions[0], timeout: "soon" }] }),
  "/verified/repository.json": repositoryJson.replace('"hristudio-official"', '"partner-lab"'),
  "/verified/plugins/index.json": json(["partner.json"]),
  "/verified/plugins/partner.json": json({ ...lab, robotId: "partner-bot", name: "Partner bot" }),
  "/copycat/repository.json": repositoryJson
    .replace('"hristudio-official"', '"copycat"')
    .replace('"HRIStudio Official Robot Plugins"', '"Copycat"'),
  "/copycat/plugins/index.json": json(["same.json", "newer.json", "simulated.json"]),
};

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const admin = f.api("admin");
let server: Server;
let base = "";

beforeAll(async () => {
  server = createServer((req, res) => (files[req.url!] ? res.end(files[req.url!]) : res.writeHead(404).end()));
  await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
  base = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
});
afterAll(async () => {
  server?.close();
  await close();
});

/** The document of `robotId` an experiment that has not chosen runs. */
const robot = async (robotId: string) =>
  (await f.api("observer").plugins.list()).robots.find((r) => r.robotId === robotId && r.isDefault);
const documentsOf = async (robotId: string) =>
  (await f.api("observer").plugins.list()).robots
    .filter((r) => r.robotId === robotId)
    .map((r) => `${r.sourceName} ${r.version} ${r.hash.slice(0, 12)}${r.isDefault ? " (default)" : ""}`);
const short = (plugin: unknown) => hashCanonical(plugin).slice(0, 12);

describe("plugin repositories", () => {
  let firstId = "";

  it("syncs a repository: good plugins stored, the bad one refused and named, the first-party robot's namesake kept beside it", async () => {
    firstId = (await admin.plugins.repositories.add({ url: `${base}/first/` })).id;
    const { changes, errors, notices } = await admin.plugins.repositories.sync({ repositoryId: firstId });
    expect(changes.map((c) => [c.robotId, c.change, c.toVersion])).toEqual([
      ["nao6-lab", "added", "1.0.0"],
      ["nao6-ros2", "added", "3.0.0"],
    ]);
    expect(errors).toHaveLength(1);
    expect(errors[0]).toMatch(/^broken\.json .*\/actions\/0\/timeout/);
    const firstParty = await f.api("observer").plugins.get({ robotId: "nao6-ros2", source: "first-party" });
    expect(notices).toEqual([
      `nao6-ros2 is also provided by nao6-ros2 3.0.0 from the first-party plugins (${short(firstParty)}) with the same version, 3.0.0: both are kept, told apart by their source and hash; this repository's is nao6-ros2 3.0.0 from the repository "HRIStudio Official Robot Plugins" (${short(nao)}). An experiment that has not chosen uses nao6-ros2 3.0.0 from the first-party plugins (${short(firstParty)}). The designer chooses which one an experiment uses.`,
    ]);
    const repository = (await admin.plugins.repositories.list()).find((r) => r.id === firstId);
    expect(repository).toMatchObject({ name: "HRIStudio Official Robot Plugins", lastSyncError: errors.join("\n") });
    expect(await robot("nao6-lab")).toMatchObject({ source: "repository", version: "1.0.0" });
    expect(await documentsOf("nao6-ros2")).toEqual([
      `the first-party plugins 3.0.0 ${short(firstParty)} (default)`,
      `the repository "HRIStudio Official Robot Plugins" 3.0.0 ${short(nao)}`,
    ]);
    expect(await f.api("observer").plugins.get({ robotId: "nao6-ros2", source: firstId })).toEqual(nao);
    expect(await f.api("observer").plugins.get({ robotId: "nao6-ros2" })).toEqual(firstParty);
    const [entry] = await db
      .select()
      .from(auditLog)
      .where(and(eq(auditLog.action, "plugins.sync"), eq(auditLog.target, firstId)));
    expect(entry?.details).toMatchObject({ notices });
  });

  it("trusts a repository only as the administrator chose: its own repository.json saying official changes nothing", async () => {
    // Added without a choice: community, and so are its plugins, though both files claim official.
    expect((await admin.plugins.repositories.list()).find((r) => r.id === firstId)).toMatchObject({
      trust: "community",
    });
    expect(await robot("nao6-lab")).toMatchObject({ trustLevel: "community" });
  });

  it("caps every plugin at the trust the administrator chose, and audits the choice", async () => {
    const verified = await admin.plugins.repositories.add({ url: `${base}/verified/`, trust: "verified" });
    await admin.plugins.repositories.sync({ repositoryId: verified.id });
    expect((await admin.plugins.repositories.list()).find((r) => r.id === verified.id)).toMatchObject({
      trust: "verified",
    });
    expect(await robot("partner-bot")).toMatchObject({ trustLevel: "verified", source: "repository" });
    const [entry] = await db
      .select()
      .from(auditLog)
      .where(and(eq(auditLog.action, "plugins.repository.add"), eq(auditLog.target, verified.id)));
    expect(entry?.details).toEqual({ url: `${base}/verified/`, trust: "verified" });
  });

  it("reports an update on the next sync, and keeps a published version immutable", async () => {
    files["/first/plugins/nao6-lab.json"] = json({ ...lab, version: "1.1.0", actions: nao.actions.slice(1) });
    const second = await admin.plugins.repositories.sync({ repositoryId: firstId });
    expect(second.changes.find((c) => c.robotId === "nao6-lab")).toMatchObject({
      change: "updated",
      fromVersion: "1.0.0",
      toVersion: "1.1.0",
      actions: { removed: [nao.actions[0].id] },
    });
    files["/first/plugins/nao6-lab.json"] = json({ ...lab, name: "Changed quietly", version: "1.1.0" });
    const third = await admin.plugins.repositories.sync({ repositoryId: firstId });
    expect(third.errors).toContain(
      "nao6-lab 1.1.0: its content changed without a new version number; the stored 1.1.0 is kept.",
    );
  });

  it("keeps another repository's copy of a robot, at the same or a newer version, and of a first-party robot, beside the original, which stays the default", async () => {
    const original = await f.api("observer").plugins.get({ robotId: "nao6-lab" });
    const simulated = await f.api("observer").plugins.get({ robotId: "simulated" });
    files["/copycat/plugins/index.json"] = json(["same.json", "simulated.json"]);
    files["/copycat/plugins/same.json"] = json({ ...original, name: "Impostor" });
    files["/copycat/plugins/simulated.json"] = json({ ...simulated, name: "Impostor" });
    // Trusted more than the original, to show trust does not make a repository a robot's default either.
    const copycat = await admin.plugins.repositories.add({ url: `${base}/copycat/`, trust: "official" });
    const first = await admin.plugins.repositories.sync({ repositoryId: copycat.id });
    expect(first.errors).toEqual([]);
    expect(first.changes.map((c) => [c.robotId, c.change])).toEqual([
      ["nao6-lab", "added"],
      ["simulated", "added"],
    ]);
    expect(first.notices).toHaveLength(2);
    expect(first.notices[0]).toMatch(
      /^nao6-lab is also provided by nao6-lab 1\.1\.0 from the repository "HRIStudio Official Robot Plugins" \([0-9a-f]{12}\) with the same version, 1\.1\.0: both are kept/,
    );
    expect(first.notices[1]).toContain(
      "An experiment that has not chosen uses simulated 1.0.0 from the first-party plugins",
    );
    // A newer version from the copycat replaces only the copycat's own.
    files["/copycat/plugins/index.json"] = json(["newer.json"]);
    files["/copycat/plugins/newer.json"] = json({ ...original, name: "Impostor", version: "9.0.0" });
    await admin.plugins.repositories.sync({ repositoryId: copycat.id });
    expect(await f.api("observer").plugins.get({ robotId: "nao6-lab" })).toEqual(original);
    expect(await f.api("observer").plugins.get({ robotId: "simulated" })).toEqual(simulated);
    expect(await robot("nao6-lab")).toMatchObject({
      version: "1.1.0",
      sourceName: 'the repository "HRIStudio Official Robot Plugins"',
    });
    expect((await documentsOf("nao6-lab")).map((d) => d.replace(/ [0-9a-f]{12}/, ""))).toEqual([
      'the repository "HRIStudio Official Robot Plugins" 1.1.0 (default)',
      'the repository "Copycat" 9.0.0',
    ]);
    expect((await f.api("observer").plugins.get({ robotId: "nao6-lab", source: copycat.id })).name).toBe("Impostor");
  });

  it("refuses an address that is not http(s), a trust that does not exist, and a repository added twice", async () => {
    await expect(
      f.httpError("admin", "plugins.repositories.add", { url: "file:///etc/passwd" }),
    ).resolves.toMatchObject({ message: "Please correct: url: must be an http:// or https:// address" });
    await expect(
      f.httpError("admin", "plugins.repositories.add", { url: `${base}/other/`, trust: "root" }),
    ).resolves.toMatchObject({ message: "Please correct: trust: must be official, verified or community" });
    await expect(admin.plugins.repositories.add({ url: `${base}/first/` })).rejects.toThrow(
      "That repository is already added.",
    );
  });
});

describe("an experiment chooses which document of its robot it runs", async () => {
  const owner = f.api("owner");
  const study = await f.newStudy();
  const experiment = await owner.experiments.create({ studyId: study.id, name: "Greeting", robotId: "nao6-ros2" });
  await owner.experiments.saveDesign({
    experimentId: experiment.id,
    baseRevision: 0,
    steps: [{ name: "Hello", actions: [{ type: "nao6-ros2.say_text", parameters: { text: "Hello" } }] }],
  });

  it("runs the first-party document until it chooses; then the repository's, in its versions, trials and rehearsals", async () => {
    const repositoryId = (await admin.plugins.repositories.list()).find((r) => r.url === `${base}/first/`)!.id;
    const firstParty = await f.api("observer").plugins.get({ robotId: "nao6-ros2", source: "first-party" });
    const before = await owner.versions.publish({ experimentId: experiment.id });
    expect(before).toMatchObject({ pluginSource: "first-party", pluginHash: hashCanonical(firstParty) });

    expect(await owner.experiments.choosePlugin({ experimentId: experiment.id, source: repositoryId })).toEqual({
      source: repositoryId,
      sourceName: 'the repository "HRIStudio Official Robot Plugins"',
      version: "3.0.0",
      hash: hashCanonical(nao),
    });
    expect(await owner.experiments.get({ experimentId: experiment.id })).toMatchObject({ pluginSource: repositoryId });
    const after = await owner.versions.publish({ experimentId: experiment.id });
    expect(after).toMatchObject({ pluginSource: repositoryId, pluginVersion: "3.0.0", pluginHash: hashCanonical(nao) });
    expect((await owner.versions.list({ experimentId: experiment.id }))[0]).toMatchObject({
      pluginSource: repositoryId,
      pluginHash: hashCanonical(nao),
    });

    // Same robotId and version, two documents: each version's trial runs its own.
    const runs = async (versionId: string) => {
      const trial = await owner.trials.create({ versionId });
      const chosen = await trialPlugin(db, trial.id);
      return chosen.ok ? hashCanonical(chosen.plugin as Plugin) : chosen.reason;
    };
    expect(await runs(before.id)).toBe(hashCanonical(firstParty));
    expect(await runs(after.id)).toBe(hashCanonical(nao));
    const rehearsal = await owner.trials.rehearse({ experimentId: experiment.id });
    const rehearsed = await trialPlugin(db, rehearsal.id);
    expect(rehearsed.ok && hashCanonical(rehearsed.plugin as Plugin)).toBe(hashCanonical(nao));
  });

  it("refuses a source that does not provide its robot, in plain words; a new robot clears the choice", async () => {
    const verified = (await admin.plugins.repositories.list()).find((r) => r.url === `${base}/verified/`)!;
    await expect(owner.experiments.choosePlugin({ experimentId: experiment.id, source: verified.id })).rejects.toThrow(
      'That source does not provide the robot "nao6-ros2": choose one of the plugin documents listed for it.',
    );
    const { draftRevision } = await owner.experiments.get({ experimentId: experiment.id });
    await owner.experiments.saveDesign({
      experimentId: experiment.id,
      baseRevision: draftRevision,
      details: { robotId: "nao6-lab" },
      steps: [],
    });
    expect(await owner.experiments.get({ experimentId: experiment.id })).toMatchObject({
      robotId: "nao6-lab",
      pluginSource: null,
    });
  });
});
