import { describe, expect, it } from "vitest";
import { MAX_NESTING, parseExpression } from "./expression";
import { httpRequest } from "./http";
import { fillTemplate, placeholders, templateProblems } from "./template";
import type { JsonValue } from "./types";

const given = { arm: "left", speed: 0.25, n: 7, on: true, off: false, text: "hi", zero: 0 };
const fill = (template: string) => {
  const filled = fillTemplate({ x: template }, given);
  return filled.ok ? (filled.value as { x: JsonValue }).x : filled;
};

describe("expressions inside {{ }}", () => {
  it.each<[string, string, JsonValue]>([
    ["a parameter, typed", "{{speed}}", 0.25],
    ["a choice between strings, in a longer string", "{{arm === 'left' ? 'L' : 'R'}}ShoulderPitch", "LShoulderPitch"],
    ["== is ===", "{{arm == \"right\" ? 'R' : 'L'}}", "L"],
    ["!==", "{{arm !== 'left'}}", false],
    ["!= is !==", "{{n != 7}}", false],
    ["no conversion in equality", "{{n === '7'}}", false],
    ["<", "{{speed < 0.5}}", true],
    ["<=", "{{n <= 6}}", false],
    [">", "{{n > 6}}", true],
    [">=", "{{n >= 8}}", false],
    ["&& gives the deciding operand", "{{on && n}}", 7],
    ["|| gives the first truthy operand", "{{zero || 0.5}}", 0.5],
    ["!", "{{!on}}", false],
    ["! of !", "{{!!text}}", true],
    ["precedence: * before +", "{{1 + 2 * 3}}", 7],
    ["brackets", "{{(1 + 2) * 3}}", 9],
    ["-", "{{n - 10}}", -3],
    ["/", "{{n / 2}}", 3.5],
    ["%", "{{n % 4}}", 3],
    ["unary minus", "{{-speed}}", -0.25],
    ["unary minus of a bracket", "{{-(n - 10)}}", 3],
    ["-{{x}} is the negated number", "-{{speed}}", -0.25],
    ["-{{x}} of zero is 0", "-{{zero}}", 0],
    ["+ joins two strings", "{{text + '!'}}", "hi!"],
    ["math.round", "{{math.round(speed * 100)}}", 25],
    ["math.floor", "{{math.floor(n / 2)}}", 3],
    ["math.ceil", "{{math.ceil(n / 2)}}", 4],
    ["math.min", "{{math.min(n, 3, 5)}}", 3],
    ["math.max", "{{math.max(speed, 1)}}", 1],
    ["math.abs", "{{math.abs(-n)}}", 7],
    ["a number inside text", "v={{n * 2}}", "v=14"],
    ["a boolean inside text", "on={{on}}", "on=true"],
    ["literals", "{{true ? null : 1}}", null],
    ["nested choice", "{{n > 5 ? (on ? 'a' : 'b') : 'c'}}", "a"],
    ["escapes in strings", "{{'it\\'s'}}", "it's"],
    ["two expressions in one string", "{{arm}}-{{n}}", "left-7"],
  ])("%s: %s", (_, template, expected) => {
    expect(fill(template)).toEqual(expected);
  });

  it.each<[string, string, string]>([
    ["a call of anything but math", "{{alert(1)}}", 'template "{{alert(1)}}" at character 8: unexpected "("'],
    ["a property", "{{arm.length}}", 'template "{{arm.length}}" at character 6: unexpected "."'],
    [
      "an unknown math function",
      "{{math.pow(2, 3)}}",
      'template "{{math.pow(2, 3)}}" at character 8: math has round, floor, ceil, min, max, abs, not "pow"',
    ],
    ["assignment", "{{n = 1}}", 'template "{{n = 1}}" at character 5: "=" is not part of the expression language'],
    ["a template literal", "{{`x`}}", 'template "{{`x`}}" at character 3: "`" is not part of the expression language'],
    ["unclosed", "{{speed", 'template "{{speed" at character 1: "{{" is not closed by "}}"'],
    ["empty", "{{}}", 'template "{{}}" at character 3: expected a value but found the end'],
    ["a missing colon", "{{on ? 1}}", 'template "{{on ? 1}}" at character 9: expected ":" but found the end'],
    ["arithmetic on text", "{{text * 2}}", 'template "{{text * 2}}" at character 8: "*" needs numbers, not "hi"'],
    [
      "+ of text and number",
      "{{text + 1}}",
      'template "{{text + 1}}" at character 8: "+" needs numbers or two strings, not "hi"',
    ],
    ["division by zero", "{{n / zero}}", 'template "{{n / zero}}" at character 5: the result is not a finite number'],
  ])("refuses %s", (_, template, reason) => {
    expect(fillTemplate({ x: template }, given)).toEqual({ ok: false, path: "/x", reason });
  });

  it("names a missing parameter as a placeholder does", () => {
    expect(fill("{{math.round(volume * 100)}}")).toEqual({
      ok: false,
      path: "/x",
      reason: 'no value for parameter "volume"',
    });
  });

  const nested = (levels: number) => `${"(".repeat(levels)}1${")".repeat(levels)}`;
  it.each<[string, string, JsonValue | string]>([
    ["brackets at the limit", nested(MAX_NESTING), 1],
    ["brackets past the limit", nested(MAX_NESTING + 1), `nested more than ${MAX_NESTING} levels deep`],
    ["minus signs at the limit", `${"-".repeat(MAX_NESTING)}1`, 1],
    ["minus signs past the limit", `${"-".repeat(MAX_NESTING + 1)}1`, `nested more than ${MAX_NESTING} levels deep`],
    ["choices at the limit", `${"on ? ".repeat(MAX_NESTING)}1${" : 0".repeat(MAX_NESTING)}`, 1],
    [
      "choices past the limit",
      `${"on ? ".repeat(MAX_NESTING + 1)}1${" : 0".repeat(MAX_NESTING + 1)}`,
      `nested more than ${MAX_NESTING} levels deep`,
    ],
    ["10,000 brackets", nested(10_000), "longer than 1000 characters"],
  ])("%s", (_, expression, expected) => {
    const parsed = parseExpression(expression);
    if (typeof expected === "string" && !parsed.ok) return expect(parsed.reason).toBe(expected);
    expect(parsed.ok).toBe(true);
    expect(fill(`{{${expression}}}`)).toEqual(expected);
  });

  it("lists the parameters an expression reads, and the strings that do not parse", () => {
    const template = { a: "{{arm === 'left' ? speed : -speed}}", b: ["{{eval('x')}}"] };
    expect(placeholders(template)).toEqual([
      { path: "/a", name: "arm" },
      { path: "/a", name: "speed" },
      { path: "/a", name: "speed" },
    ]);
    expect(templateProblems(template)).toEqual([
      { path: "/b/0", reason: `template "{{eval('x')}}" at character 7: unexpected "("` },
    ]);
  });
});

describe("expressions in an HTTP action's URL", () => {
  it("fills each expression URL-encoded, never the literal template", () => {
    const dispatch = { method: "POST" as const, url: "say/{{arm === 'left' ? 'L R' : 'x'}}?n={{n * 2}}" };
    expect(httpRequest(dispatch, "http://robot.local/api/", given)).toEqual({
      ok: true,
      method: "POST",
      url: "http://robot.local/api/say/L%20R?n=14",
    });
    expect(httpRequest({ ...dispatch, url: "say/{{arm.x}}" }, "http://robot.local/", given)).toEqual({
      ok: false,
      reason: '/url: template "say/{{arm.x}}" at character 10: unexpected "."',
    });
  });
});

describe("a template nested past 64 levels", () => {
  const deep = (levels: number): JsonValue => (levels === 0 ? "{{n}}" : { a: deep(levels - 1) });
  const at = (levels: number) => "/a".repeat(levels);
  it("is filled at 64 levels, and refused, not sent unfilled, at 65", () => {
    expect(fillTemplate(deep(64), given).ok).toBe(true);
    expect(fillTemplate(deep(65), given)).toEqual({
      ok: false,
      path: at(65),
      reason: "nested more than 64 levels deep",
    });
    expect(templateProblems(deep(65))).toEqual([
      { path: at(65), reason: "the template is nested more than 64 levels deep" },
    ]);
  });
});
