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

describe("the plugin core stays pure", () => {
  it("imports no I/O and nothing outside the core (the schema file aside)", async () => {
    const { readdirSync } = await import("node:fs");
    const sources = readdirSync("src/core/plugins").filter((f) => f.endsWith(".ts") && !f.endsWith(".test.ts"));
    for (const file of sources) {
      const imports = [...read(`src/core/plugins/${file}`).matchAll(/from "([^"]+)"/g)].map((m) => m[1]!);
      for (const target of imports) {
        const allowed = target.startsWith("./") || target === "../trial/types" || target === "ajv" || target === "../../../plugins/plugin.schema.json";
        expect(allowed, `${file} imports ${target}`).toBe(true);
      }
    }
  });
});
