import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, parsePluginIndex, parseRepository } from "./index";

const fixtures = "tests/fixtures/hristudio-plugins";
const read = (path: string) => readFileSync(path, "utf8");

describe("HRIStudio files load unmodified", () => {
  it("loads the fixture NAO6 plugin", () => {
    const result = loadPlugin("nao6-ros2.json", read(`${fixtures}/plugins/nao6-ros2.json`));
    expect(result.ok ? [] : result.errors).toEqual([]);
    if (result.ok) expect(result.value.actions).toHaveLength(20);
  });
  it("parses repository.json and plugins/index.json", () => {
    const repo = parseRepository("repository.json", read(`${fixtures}/repository.json`));
    expect(repo.ok && repo.value.id).toBe("hristudio-official");
    const index = parsePluginIndex("plugins/index.json", read(`${fixtures}/plugins/index.json`));
    expect(index.ok && index.value).toEqual(["turtlebot3-burger.json", "turtlebot3-waffle.json", "nao6-ros2.json"]);
  });
});

describe("bad repository files", () => {
  it.each([
    [
      "plugins/index.json",
      '["../../etc/passwd.json"]',
      [{ path: "/0", reason: "must be a plugin file name ending in .json, without folders" }],
    ],
    [
      "plugins/index.json",
      '["a.json", "a.json"]',
      [{ path: "", reason: "lists the same value twice (numbers 1 and 2)" }],
    ],
    ["plugins/index.json", '{"plugins": []}', [{ path: "", reason: "must be a list" }]],
    ["repository.json", '{"name": "x"}', [{ path: "/id", reason: "is required but missing" }]],
    [
      "repository.json",
      '{"id": "x", "name": "x", "trust": "total"}',
      [{ path: "/trust", reason: 'must be one of: "official", "verified", "community"' }],
    ],
  ])("%s %s", (file, text, expected) => {
    const result = file === "repository.json" ? parseRepository(file, text) : parsePluginIndex(file, text);
    expect(result.ok ? [] : result.errors).toEqual(expected.map((e) => ({ file, code: "schema", ...e })));
  });

  it("gives line and column for invalid JSON", () => {
    expect(parsePluginIndex("plugins/index.json", '[\n  "a.json"\n  "b.json"\n]')).toEqual({
      ok: false,
      errors: [
        {
          file: "plugins/index.json",
          path: "",
          code: "invalid_json",
          reason: 'invalid JSON: expected "," or "]" in a list, found "\\""',
          line: 3,
          column: 3,
        },
      ],
    });
  });
});
