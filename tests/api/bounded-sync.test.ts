// A sync is bounded and honest. Served by a real local HTTP server: a plugin
// whose payload nests 10,000 levels, one whose parameter schema does, a file
// that says it is 50 MB and one whose body never ends are each refused with
// the limit named, and the rest of the repository still syncs; the endless
// body is read no further than the limit. A robot the index stops listing is
// no longer offered, its pinned version keeps running, and the report names
// the experiments still using it, once.
import { createServer, type Server } from "node:http";
import type { AddressInfo } from "node:net";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { Plugin } from "../../src/core/plugins";
import { MAX_FILE_BYTES } from "../../src/robots/repository-sync";
import { trialPlugin } from "../../src/robots/trial-plugin";
import { freshDatabase } from "../support/db";
import { buildFixture } from "./fixture";

const base = JSON.parse(readFileSync(join(import.meta.dirname, "..", "fixtures", "plugins", "base.json"), "utf8"));
const bot = (robotId: string): Plugin => ({ ...base, robotId, name: robotId, version: "1.0.0" });
const LEVELS = 10_000;
const deep = (inner: string) => `${"[".repeat(LEVELS)}${inner}${"]".repeat(LEVELS)}`;
// The text of a plugin with `at` (a JSON string somewhere in it) replaced by 10,000 levels of nesting.
const nestedAt = (robotId: string, at: string, nesting: string) =>
  JSON.stringify({ ...bot(robotId), marker: at }).replace(`"${at}"`, nesting);
const schemaNesting = `${'{"type":"object","properties":{"a":'.repeat(LEVELS)}{"type":"string"}${"}}".repeat(LEVELS)}`;

const files: Record<string, string> = {
  "/repository.json": JSON.stringify({ id: "lab", name: "Our lab" }),
  "/plugins/index.json": JSON.stringify([
    "kept.json",
    "deep-payload.json",
    "deep-schema.json",
    "declared-huge.json",
    "endless.json",
    "other.json",
  ]),
  "/plugins/kept.json": JSON.stringify(bot("kept-bot")),
  "/plugins/other.json": JSON.stringify(bot("other-bot")),
  "/plugins/deep-payload.json": nestedAt("deep-payload", "payload", deep("0")),
  "/plugins/deep-schema.json": nestedAt("deep-schema", "schema", schemaNesting),
};
/** What the server wrote of the endless body before the client stopped reading it. */
let endless: Promise<number> = Promise.resolve(0);

const { db, close } = await freshDatabase();
const f = await buildFixture(db);
const admin = f.api("admin");
let server: Server;
let repositoryId = "";
const sync = () => admin.plugins.repositories.sync({ repositoryId });
const offered = async () => (await f.api("observer").plugins.list()).robots.map((r) => r.robotId);

beforeAll(async () => {
  server = createServer((req, res) => {
    if (req.url === "/plugins/declared-huge.json") {
      res.writeHead(200, { "content-length": String(50 * 1024 * 1024) });
      res.write("[");
      return;
    }
    if (req.url === "/plugins/endless.json") {
      endless = new Promise((done) => {
        let written = 0;
        const chunk = Buffer.alloc(64 * 1024, " ");
        const more = () => {
          while (!res.destroyed) {
            written += chunk.length;
            if (!res.write(chunk)) return;
          }
        };
        res.on("drain", more);
        res.on("close", () => done(written));
        res.writeHead(200);
        more();
      });
      return;
    }
    const body = files[req.url!];
    if (body === undefined) res.writeHead(404).end();
    else res.end(body);
  });
  await new Promise<void>((ok) => server.listen(0, "127.0.0.1", ok));
  const url = `http://127.0.0.1:${(server.address() as AddressInfo).port}/`;
  repositoryId = (await admin.plugins.repositories.add({ url })).id;
});
afterAll(async () => {
  server?.closeAllConnections();
  server?.close();
  await close();
});

describe("a bounded sync", () => {
  it("refuses the nested and oversized files, each naming its limit, and syncs the rest", async () => {
    const report = await sync();
    expect(report.changes.map((c) => [c.robotId, c.change])).toEqual([
      ["kept-bot", "added"],
      ["other-bot", "added"],
    ]);
    const nested = "nested more than 256 levels deep (lists and objects inside each other), the limit for a file";
    const tooLarge = (file: string, declared: string) =>
      `plugins/${file} at /: http://127.0.0.1:${(server.address() as AddressInfo).port}/plugins/${file} is larger than 1 MB, the most a repository's file may be${declared}: reading stopped at the limit`;
    // Where the 257th level opens, as line and column: found by the same count, so only its shape is checked here.
    expect(report.errors.map((e) => e.replace(/^(deep-[a-z]+\.json):1:\d+:/, "$1:1:N:"))).toEqual([
      `deep-payload.json:1:N: ${nested}`,
      `deep-schema.json:1:N: ${nested}`,
      tooLarge("declared-huge.json", " (it says 50 MB)"),
      tooLarge("endless.json", ""),
    ]);
    expect(await offered()).toEqual(expect.arrayContaining(["kept-bot", "other-bot"]));
    expect(await offered()).not.toContain("deep-payload");
  });

  it("reads the endless body no further than the limit: the connection is closed, not drained", async () => {
    const written = await endless;
    // What the sockets' buffers took on top of the limit; without a limit it runs on until the 10 s timeout.
    expect(written).toBeGreaterThan(MAX_FILE_BYTES);
    expect(written).toBeLessThan(MAX_FILE_BYTES * 16);
  });
});

describe("a robot the repository stops listing", () => {
  const owner = f.api("owner");
  let trialId = "";

  it("is kept while a file of the index could not be read: it may be the one that offers it", async () => {
    const study = await f.newStudy("Removal study");
    const experiment = await owner.experiments.create({
      studyId: study.id,
      name: "Greeting",
      robotId: "other-bot",
    });
    await owner.experiments.saveDesign({
      experimentId: experiment.id,
      baseRevision: 0,
      steps: [{ name: "Hello", actions: [{ type: "other-bot.say_text", parameters: { text: "Hello" } }] }],
    });
    const version = await owner.versions.publish({ experimentId: experiment.id });
    trialId = (await owner.trials.create({ versionId: version.id })).id;
    files["/plugins/index.json"] = JSON.stringify(["kept.json", "missing.json"]);
    const report = await sync();
    expect(report.changes.filter((c) => c.change === "removed")).toEqual([]);
    expect(report.notices).toEqual([
      "other-bot was not among the plugins read this time, as not every file of the repository could be read: kept as before until a sync reads them all.",
    ]);
    expect(await offered()).toContain("other-bot");
  });

  it("is no longer offered once the whole index is read, and the report names the experiments still using it", async () => {
    files["/plugins/index.json"] = JSON.stringify(["kept.json"]);
    const report = await sync();
    expect(report.changes.filter((c) => c.change !== "unchanged").map((c) => [c.robotId, c.change])).toEqual([
      ["other-bot", "removed"],
    ]);
    expect(report.notices).toEqual([
      `other-bot is no longer listed by the repository "Our lab": it is not offered for new experiments any more. Versions published with it keep running with the document they pinned. Experiments still using it: "Greeting" (study "Removal study"); they keep their published versions, and a new version needs another plugin of other-bot.`,
    ]);
    expect(await offered()).toContain("kept-bot");
    expect(await offered()).not.toContain("other-bot");
  });

  it("keeps running the pinned version from its stored document", async () => {
    expect(await trialPlugin(db, trialId)).toMatchObject({ ok: true, robotId: "other-bot", plugin: bot("other-bot") });
  });

  it("is not reported again at the next sync", async () => {
    const report = await sync();
    expect(report.changes.filter((c) => c.change !== "unchanged")).toEqual([]);
    expect(report.notices).toEqual([]);
    expect(report.errors).toEqual([]);
  });
});
