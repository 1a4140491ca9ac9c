// Syncing a plugin repository over real HTTP from a local server.
import { readFile } from "node:fs/promises";
import { createServer, type Server } from "node:http";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { loadPlugin, pluginChanges, unavailableActions, type Plugin } from "../../src/core/plugins";
import { fetchRepository } from "../../src/robots/repository-sync";

const fixtures = "tests/fixtures/hristudio-plugins";
let server: Server;
let base = "";
const files: Record<string, string> = {};

beforeAll(async () => {
  const nao = await readFile(`${fixtures}/plugins/nao6-ros2.json`, "utf8");
  const repository = await readFile(`${fixtures}/repository.json`, "utf8");
  Object.assign(files, {
    "/official/repository.json": repository,
    "/official/plugins/index.json": await readFile(`${fixtures}/plugins/index.json`, "utf8"),
    "/official/plugins/nao6-ros2.json": nao,
    "/official/plugins/turtlebot3-burger.json": await readFile(`${fixtures}/plugins/turtlebot3-burger.json`, "utf8"),
    "/official/plugins/turtlebot3-waffle.json": await readFile(`${fixtures}/plugins/turtlebot3-waffle.json`, "utf8"),
    "/mixed/repository.json": repository.replace('"trust": "official"', '"trust": "community"'),
    "/mixed/plugins/index.json": '["nao6-ros2.json", "broken.json", "missing.json"]',
    "/mixed/plugins/nao6-ros2.json": nao,
    "/mixed/plugins/broken.json": nao.replace('"robotId": "nao6-ros2"', '"robotId": "NAO 6"'),
    "/no-index/repository.json": repository,
  });
  server = createServer((request, response) => {
    const body = files[request.url ?? ""];
    response.writeHead(body === undefined ? 404 : 200, { "content-type": "application/json" }).end(body ?? "not found");
  });
  await new Promise<void>((resolve) => server.listen(0, "127.0.0.1", resolve));
  base = `http://127.0.0.1:${(server.address() as { port: number }).port}`;
});
afterAll(() => new Promise<void>((resolve) => server.close(() => resolve())));

describe("fetchRepository", () => {
  it("fetches the official repository with all three plugins, unmodified, the Waffle's three actions we cannot run marked", async () => {
    const result = await fetchRepository(`${base}/official`);
    expect(result.errors).toEqual([]);
    expect(result.repository?.id).toBe("hristudio-official");
    expect(result.plugins.map((p) => [p.file, p.plugin.robotId, p.plugin.version, p.trust])).toEqual([
      ["turtlebot3-burger.json", "turtlebot3-burger", "2.0.0", "official"],
      ["turtlebot3-waffle.json", "turtlebot3-waffle", "2.0.0", "official"],
      ["nao6-ros2.json", "nao6-ros2", "3.0.0", "verified"],
    ]);
    expect(result.plugins.map((p) => [p.plugin.robotId, unavailableActions(p.plugin).map((u) => u.actionId)])).toEqual([
      ["turtlebot3-burger", []],
      ["turtlebot3-waffle", ["capture_image", "scan_environment", "follow_wall"]],
      ["nao6-ros2", []],
    ]);
  });

  it("keeps the good plugins, reports the bad and the missing, and caps trust at the repository's", async () => {
    const result = await fetchRepository(`${base}/mixed/`);
    expect(result.plugins.map((p) => [p.plugin.robotId, p.trust])).toEqual([["nao6-ros2", "community"]]);
    expect(result.errors).toEqual([
      {
        file: "broken.json",
        path: "/robotId",
        code: "schema",
        reason: 'must be lower-case letters, digits, "-" or "_", starting with a letter or digit',
      },
      {
        file: "plugins/missing.json",
        path: "",
        code: "unreadable",
        reason: `cannot fetch ${base}/mixed/plugins/missing.json: HTTP 404`,
      },
    ]);
  });

  it("reports a repository without an index", async () => {
    const result = await fetchRepository(`${base}/no-index`);
    expect(result.repository?.id).toBe("hristudio-official");
    expect(result.errors.map((e) => e.file)).toEqual(["plugins/index.json"]);
  });

  it("reports an unreachable repository instead of throwing", async () => {
    const result = await fetchRepository("http://127.0.0.1:1/");
    expect(result.plugins).toEqual([]);
    expect(result.errors[0]).toMatchObject({ file: "repository.json", code: "unreadable" });
  });
});

describe("pluginChanges", () => {
  const load = async (path: string) => (loadPlugin(path, await readFile(path, "utf8")) as { value: Plugin }).value;

  it("shows what a sync changed", async () => {
    const before = [await load(`${fixtures}/plugins/nao6-ros2.json`), await load("plugins/turtlebot3-burger.json")];
    const ours = await load("plugins/nao6-ros2.json");
    const after = [{ ...ours, version: "3.1.0" }, await load("plugins/pepper-ros2.json"), before[1]!];
    expect(pluginChanges(before, after)).toEqual([
      {
        robotId: "nao6-ros2",
        change: "updated",
        fromVersion: "3.0.0",
        toVersion: "3.1.0",
        actions: {
          added: ["look_down", "play_animation", "stop_speech", "stop_animation"],
          removed: [],
          // Ours declare how speech and animations are known to be done.
          changed: [
            "say_text",
            "say_with_emotion",
            ...["bow", "hey", "show_floor", "enthusiastic", "yes", "no", "idontknow"].map((a) => `play_animation_${a}`),
          ],
        },
      },
      {
        robotId: "pepper-ros2",
        change: "added",
        fromVersion: undefined,
        toVersion: "1.0.0",
        actions: { added: expect.any(Array), removed: [], changed: [] },
      },
      {
        robotId: "turtlebot3-burger",
        change: "unchanged",
        fromVersion: "1.0.0",
        toVersion: "1.0.0",
        actions: { added: [], removed: [], changed: [] },
      },
    ]);
  });
});
