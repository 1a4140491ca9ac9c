// The malformed corpus: every bad plugin file gets its precise error (file,
// JSON path, reason), and hostile parameters get theirs. Nothing throws.
import { readdirSync, readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, resolveAction, type Plugin } from "../../src/core/plugins";

const dir = "tests/fixtures/plugins";
const expected = JSON.parse(readFileSync(`${dir}/malformed.expected.json`, "utf8")) as Record<string, unknown[]>;
const files = readdirSync(`${dir}/malformed`).sort();

describe("malformed plugin files", () => {
  it("has at least 30 files, each with an expectation", () => {
    expect(files.length).toBeGreaterThanOrEqual(30);
    expect(Object.keys(expected).sort()).toEqual(files);
  });

  it.each(files)("%s", (file) => {
    const result = loadPlugin(file, readFileSync(`${dir}/malformed/${file}`, "utf8"));
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.errors).toEqual(expected[file]);
  });
});

interface HostileCase {
  case: string;
  type: string;
  parameters: unknown;
  expect: { status: string; reason?: string; problems?: unknown[] };
}

describe("hostile parameters", () => {
  const base = loadPlugin("base.json", readFileSync(`${dir}/base.json`, "utf8"));
  const plugin = (base.ok ? base.value : null) as Plugin;
  const cases = JSON.parse(readFileSync(`${dir}/hostile-parameters.json`, "utf8")) as HostileCase[];

  it("the base plugin they run against loads", () => expect(base.ok).toBe(true));

  it.each(cases.map((c) => [c.case, c] as const))("%s", (_, c) => {
    const resolution = resolveAction(plugin, c.type, c.parameters);
    const got = { status: resolution.status } as HostileCase["expect"];
    if (resolution.status === "unsupported") got.reason = resolution.reason;
    if (resolution.status === "parameter_problems") got.problems = resolution.problems;
    expect(got).toEqual(c.expect);
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });
});
