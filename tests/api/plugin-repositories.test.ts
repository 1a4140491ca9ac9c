// An administrator adds a plugin repository; sync fetches it over real HTTP,
// keeps the good plugins (the HRIStudio fixture unmodified), refuses the bad
// one with file, path and reason, and reports what changed.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const FIXTURE = join(import.meta.dirname, "..", "fixtures", "hristudio-plugins");
const nao = JSON.parse(readFileSync(join(FIXTURE, "plugins", "nao6-ros2.json"), "utf8"));
const files: Record<string, string> = {
  "/repository.json": readFileSync(join(FIXTURE, "repository.json"), "utf8"),
  "/plugins/nao6-ros2.json": readFileSync(join(FIXTURE, "plugins", "nao6-ros2.json"), "utf8"),
  "/plugins/index.json": JSON.stringify(["nao6-ros2.json", "nao6-lab.json", "broken.json"]),
  "/plugins/nao6-lab.json": JSON.stringify({ ...nao, robotId: "nao6-lab", name: "NAO6 (our lab)", version: "1.0.0" }),
  "/plugins/broken.json": JSON.stringify({ ...nao, robotId: "broken", actions: [{ ...nao.actions[0], timeout: "soon" }] }),
};

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const admin = f.api("admin");
let server: Server;
let url = "";

beforeAll(async () => {
  server = createServer((req, res) => (files[req.url!] ? res.end(files[req.url!]) : res.writeHead(404).end()));
  await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
  url = `http://127.0.0.1:${(server.address() as AddressInfo).port}/`;
});
afterAll(async () => {
  server?.close();
  await close();
});

describe("plugin repositories", () => {
  let repositoryId = "";

  it("syncs a repository: good plugins stored with the repository's trust, the bad one refused and named", async () => {
    repositoryId = (await admin.plugins.repositories.add({ url })).id;
    const { changes, errors } = await admin.plugins.repositories.sync({ repositoryId });
    expect(changes.map((c) => [c.robotId, c.change, c.toVersion])).toEqual([
      ["nao6-lab", "added", "1.0.0"],
      ["nao6-ros2", "added", "3.0.0"],
    ]);
    expect(errors).toHaveLength(1);
    expect(errors[0]).toMatch(/^broken\.json .*\/actions\/0\/timeout/);
    const [repository] = await admin.plugins.repositories.list();
    expect(repository).toMatchObject({ name: "HRIStudio Official Robot Plugins", trust: "official", lastSyncError: errors[0] });
    const robots = (await f.api("observer").plugins.list()).robots;
    expect(robots.find((r) => r.robotId === "nao6-lab")).toMatchObject({ source: "repository", version: "1.0.0" });
    expect(robots.find((r) => r.robotId === "nao6-ros2")).toMatchObject({ source: "first-party" });
  });

  it("reports an update on the next sync, and keeps a published version immutable", async () => {
    files["/plugins/nao6-lab.json"] = JSON.stringify({ ...nao, robotId: "nao6-lab", name: "NAO6 (our lab)", version: "1.1.0", actions: nao.actions.slice(1) });
    const second = await admin.plugins.repositories.sync({ repositoryId });
    expect(second.changes.find((c) => c.robotId === "nao6-lab")).toMatchObject({ change: "updated", fromVersion: "1.0.0", toVersion: "1.1.0", actions: { removed: [nao.actions[0].id] } });
    files["/plugins/nao6-lab.json"] = JSON.stringify({ ...nao, robotId: "nao6-lab", name: "Changed quietly", version: "1.1.0" });
    const third = await admin.plugins.repositories.sync({ repositoryId });
    expect(third.errors).toContain("nao6-lab 1.1.0: its content changed without a new version number; the stored 1.1.0 is kept.");
  });

  it("refuses an address that is not http(s), and a repository added twice", async () => {
    await expect(f.httpError("admin", "plugins.repositories.add", { url: "file:///etc/passwd" })).resolves.toMatchObject({ message: "Please correct: url: must be an http:// or https:// address" });
    await expect(admin.plugins.repositories.add({ url })).rejects.toThrow("That repository is already added.");
  });
});
