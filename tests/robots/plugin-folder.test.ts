import { mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, describe, expect, it } from "vitest";
import { loadPluginFolder } from "../../src/robots/plugin-folder";

const fixture = "tests/fixtures/hristudio-plugins/plugins/nao6-ros2.json";

describe("first-party plugins", () => {
  it("load through the public loader with no errors", async () => {
    const folder = await loadPluginFolder("plugins");
    expect(folder.errors).toEqual([]);
    expect(folder.plugins.map((p) => p.robotId).sort()).toEqual([
      "nao6-ros2",
      "pepper-ros2",
      "simulated",
      "turtlebot3-burger",
    ]);
  });

  it("our NAO6 file is the fixture plus additive fields only", async () => {
    const original = JSON.parse(await readFile(fixture, "utf8"));
    const ours = JSON.parse(await readFile("plugins/nao6-ros2.json", "utf8"));
    for (const [key, value] of Object.entries(original)) {
      if (key === "actions") continue;
      expect(ours[key], key).toEqual(value);
    }
    // An action's own additions (how it is known to be done) are ours; all else is the fixture's.
    const withoutOurs = ({ completion: _, ...action }: Record<string, unknown>) => action;
    expect(ours.actions.slice(0, original.actions.length).map(withoutOurs)).toEqual(original.actions);
  });
});

describe("a folder with a bad file (fail soft)", () => {
  let dir = "";
  afterAll(() => rm(dir, { recursive: true, force: true }));

  it("keeps the good plugins and names the bad file", async () => {
    dir = await mkdtemp(join(tmpdir(), "plugins-"));
    const good = await readFile(fixture, "utf8");
    await writeFile(join(dir, "a-good.json"), good);
    await writeFile(join(dir, "b-broken.json"), good.replace('"timeout": 5000', '"timeout": "5s"'));
    await writeFile(join(dir, "c-same-robot.json"), good);
    await writeFile(join(dir, "index.json"), '["a-good.json"]');
    const folder = await loadPluginFolder(dir);
    expect(folder.plugins.map((p) => p.robotId)).toEqual(["nao6-ros2"]);
    expect(folder.errors).toEqual([
      { file: "b-broken.json", path: "/actions/2/timeout", code: "schema", reason: "must be a whole number" },
      {
        file: "c-same-robot.json",
        path: "/robotId",
        code: "duplicate_robot",
        reason: 'robotId "nao6-ros2" is already declared by a-good.json',
      },
    ]);
  });

  it("reports a missing folder instead of throwing", async () => {
    const folder = await loadPluginFolder("/no/such/folder");
    expect(folder.plugins).toEqual([]);
    expect(folder.errors[0]).toMatchObject({ file: "/no/such/folder", code: "unreadable" });
  });
});
