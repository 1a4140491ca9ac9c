import { describe, expect, it } from "vitest";
import { finish } from "../work";
import { canonicalJson, canonicalPieces, hashCanonical, hashing } from "./canonical";

describe("canonical JSON", () => {
  it.each<[string, unknown, string]>([
    [
      "sorts keys at every depth",
      { b: 1, a: { d: [3, { z: 1, y: 2 }], c: null } },
      '{"a":{"c":null,"d":[3,{"y":2,"z":1}]},"b":1}',
    ],
    ["keeps array order", [3, 1, 2], "[3,1,2]"],
    ["drops undefined values", { a: undefined, b: 1 }, '{"b":1}'],
    ["escapes text the JSON way", { t: 'quote " brace { newline \n' }, '{"t":"quote \\" brace { newline \\n"}'],
  ])("%s", (_name, value, expected) => {
    expect(canonicalJson(value)).toBe(expected);
  });

  it.each([[Number.NaN], [Number.POSITIVE_INFINITY]])("refuses %s and says where", (bad) => {
    expect(() => canonicalJson({ steps: [{ seconds: bad }] })).toThrow(
      `$.steps[0].seconds: ${bad} cannot be stored as JSON`,
    );
  });

  it("writes a value nested 100,000 deep, and the deepest bad number's place", () => {
    // Deeper than JSON.stringify itself can go, so the expected text is made the same way, from the inside out.
    let deep: unknown = 1;
    let expected = "1";
    for (let i = 0; i < 100_000; i++) {
      deep = i % 2 ? [deep] : { k: deep };
      expected = i % 2 ? `[${expected}]` : `{"k":${expected}}`;
    }
    expect(canonicalJson(deep) === expected).toBe(true);
    let bad: unknown = Number.NaN;
    for (let i = 0; i < 3; i++) bad = { k: [bad] };
    expect(() => canonicalJson(bad)).toThrow("$.k[0].k[0].k[0]: NaN cannot be stored as JSON");
  });

  it("comes in pieces that make the whole text, hashed as the whole", () => {
    const large = { steps: Array.from({ length: 20_000 }, (_, i) => ({ id: `s${i}`, text: "x".repeat(20) })) };
    const pieces = [...canonicalPieces(large)];
    expect(pieces.length).toBeGreaterThan(1);
    expect(pieces.join("")).toBe(canonicalJson(large));
    expect(finish(hashing(large))).toEqual({ text: canonicalJson(large), hash: hashCanonical(large) });
  });

  it("hashes equal designs equally, whatever their key order", () => {
    expect(hashCanonical({ a: 1, b: [1, 2] })).toBe(hashCanonical({ b: [1, 2], a: 1 }));
    expect(hashCanonical({ a: 1 })).not.toBe(hashCanonical({ a: 2 }));
    expect(hashCanonical({})).toBe("44136fa355b3678a1146ad16f7e8649e94fb4fc21fe77e8310c060f61caaff8a");
  });
});
