import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { checkDocument, loadPlugin, parseJson, parsePluginIndex } from "./index";
import { MAX_DEPTH, nestedTooDeep } from "./json-text";

const nao = readFileSync("tests/fixtures/hristudio-plugins/plugins/nao6-ros2.json", "utf8");
const nested = (levels: number) => `${"[".repeat(levels)}${"]".repeat(levels)}`;
/** NAO's file with its first payload's `linear` nested `levels` lists deep. */
const deepPayload = (levels: number) =>
  nao.replace(/"linear": \{/, `"linear": ${"[".repeat(levels)}0${"]".repeat(levels)}, "x": {`);

describe("how deep a file may nest", () => {
  it.each([
    ["lists nested to the limit load", nested(MAX_DEPTH), null],
    ["one level more is refused where it opens", nested(MAX_DEPTH + 1), MAX_DEPTH + 1],
    ["10,000 levels are refused at the same place", nested(10_000), MAX_DEPTH + 1],
    ["brackets inside a string do not count", JSON.stringify("[".repeat(10_000)), null],
    ["nor after an escaped quote inside a string", `"\\"${"{".repeat(10_000)}"`, null],
    ["objects nested 10,000 levels are refused", `${'{"a":'.repeat(10_000)}1${"}".repeat(10_000)}`, MAX_DEPTH * 5 + 1],
  ])("%s", (_name, text, column) => {
    const parsed = parseJson("f.json", text);
    if (column === null) expect(parsed.ok).toBe(true);
    else
      expect(parsed).toEqual({
        ok: false,
        errors: [{ file: "f.json", path: "", code: "too_deep", reason: nestedTooDeep, line: 1, column }],
      });
  });

  it("a plugin whose payload nests 10,000 levels is refused for that, naming the limit and where", () => {
    expect(deepPayload(3)).not.toBe(nao);
    expect(loadPlugin("deep.json", deepPayload(10_000))).toEqual({
      ok: false,
      errors: [expect.objectContaining({ file: "deep.json", path: "", code: "too_deep", reason: nestedTooDeep })],
    });
  });

  it("an index nested 10,000 levels is refused the same way", () => {
    const result = parsePluginIndex("plugins/index.json", nested(10_000));
    expect(!result.ok && result.errors.map((e) => e.code)).toEqual(["too_deep"]);
  });

  it("a document parsed elsewhere is measured without recursion, and the first too deep part named", () => {
    let deep: unknown = 0;
    for (let i = 0; i < 10_000; i++) deep = { inner: deep };
    const document = { ...JSON.parse(nao), extra: deep };
    const result = checkDocument("deep.json", document);
    expect(!result.ok && result.errors).toEqual([
      { file: "deep.json", path: `/extra${"/inner".repeat(MAX_DEPTH - 1)}`, code: "too_deep", reason: nestedTooDeep },
    ]);
  });
});
