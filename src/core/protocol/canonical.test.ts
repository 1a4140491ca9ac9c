import { describe, expect, it } from "vitest";
import { canonicalJson, hashCanonical } from "./canonical";

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

  it("hashes equal designs equally, whatever their key order", () => {
    expect(hashCanonical({ a: 1, b: [1, 2] })).toBe(hashCanonical({ b: [1, 2], a: 1 }));
    expect(hashCanonical({ a: 1 })).not.toBe(hashCanonical({ a: 2 }));
    expect(hashCanonical({})).toBe("44136fa355b3678a1146ad16f7e8649e94fb4fc21fe77e8310c060f61caaff8a");
  });
});
