import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, parsePluginIndex, parseRepository } from "./index";

const fixtures = "../shared/fixtures/hristudio-plugins";
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
    expect(index.ok && index.value).toEqual(["nao6-ros2.json"]);
  });
});
