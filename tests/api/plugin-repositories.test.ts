// An administrator adds a plugin repository with the trust they choose; sync
// fetches it over real HTTP, keeps the good plugins (the HRIStudio fixture
// unmodified), refuses the bad one with file, path and reason, never lets a
// repository take a robot another source provides, and reports what changed.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { and, eq } from "drizzle-orm";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
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

const robot = async (robotId: string) =>
  (await f.api("observer").plugins.list()).robots.find((r) => r.robotId === robotId);

describe("plugin repositories", () => {
  let firstId = "";

  it("syncs a repository: good plugins stored, the bad one and a first-party robot refused and named", async () => {
    firstId = (await admin.plugins.repositories.add({ url: `${base}/first/` })).id;
    const { changes, errors } = await admin.plugins.repositories.sync({ repositoryId: firstId });
    expect(changes.map((c) => [c.robotId, c.change, c.toVersion])).toEqual([["nao6-lab", "added", "1.0.0"]]);
    expect(errors).toHaveLength(2);
    expect(errors[0]).toMatch(/^broken\.json .*\/actions\/0\/timeout/);
    expect(errors[1]).toBe(
      "nao6-ros2 is already provided by the first-party plugins; this repository's copy was not installed.",
    );
    const repository = (await admin.plugins.repositories.list()).find((r) => r.id === firstId);
    expect(repository).toMatchObject({ name: "HRIStudio Official Robot Plugins", lastSyncError: errors.join("\n") });
    expect(await robot("nao6-lab")).toMatchObject({ source: "repository", version: "1.0.0" });
    expect(await robot("nao6-ros2")).toMatchObject({ source: "first-party", version: "3.0.0" });
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

  it("refuses another repository's copy of a robot, at the same or a newer version, and of a first-party robot; the original still loads", async () => {
    const original = await f.api("observer").plugins.get({ robotId: "nao6-lab" });
    files["/copycat/plugins/same.json"] = json({ ...original, name: "Impostor" });
    files["/copycat/plugins/newer.json"] = json({ ...original, name: "Impostor", version: "9.0.0" });
    const simulated = await f.api("observer").plugins.get({ robotId: "simulated" });
    files["/copycat/plugins/simulated.json"] = json({ ...simulated, name: "Impostor" });
    // Trusted more than the original, to show trust does not let a repository take a robot either.
    const copycat = await admin.plugins.repositories.add({ url: `${base}/copycat/`, trust: "official" });
    const { changes, errors } = await admin.plugins.repositories.sync({ repositoryId: copycat.id });
    const refused =
      'nao6-lab is already provided by the repository "HRIStudio Official Robot Plugins"; this repository\'s copy was not installed.';
    expect(errors).toEqual([
      refused,
      refused,
      "simulated is already provided by the first-party plugins; this repository's copy was not installed.",
    ]);
    expect(changes).toEqual([]);
    expect(await f.api("observer").plugins.get({ robotId: "nao6-lab" })).toEqual(original);
    expect(await f.api("observer").plugins.get({ robotId: "simulated" })).toEqual(simulated);
    expect(await robot("nao6-lab")).toMatchObject({
      version: "1.1.0",
      sourceName: 'the repository "HRIStudio Official Robot Plugins"',
    });
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
