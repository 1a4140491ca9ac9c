// The value of a parsed expression (expression.ts) given the action's
// parameters. Typed as JSON is: arithmetic and comparison of order take
// numbers only, `+` joins two strings or adds two numbers, equality never
// converts, and a result that is not a finite number is refused rather than
// sent (a robot reads NaN or Infinity as nothing it can use).
import type { BinaryOp, Node } from "./expression";
import type { JsonValue } from "./types";

export type Evaluated = { ok: true; value: JsonValue } | { ok: false; at: number; reason: string };

/** `lookup` gives a parameter's value, or undefined when the action has none. */
export function evaluate(node: Node, lookup: (name: string) => JsonValue | undefined): Evaluated {
  try {
    return { ok: true, value: value(node, lookup) };
  } catch (error) {
    if (error instanceof Failed) return { ok: false, at: error.at, reason: error.message };
    throw error;
  }
}

class Failed extends Error {
  constructor(
    readonly at: number,
    reason: string,
  ) {
    super(reason);
  }
}

// JavaScript's truthiness, the one HRIStudio's authors expect of `!`, `&&`, `||` and `? :`.
const truthy = (v: JsonValue) => !(v === false || v === null || v === 0 || v === "");

function value(node: Node, lookup: (name: string) => JsonValue | undefined): JsonValue {
  switch (node.kind) {
    case "literal":
      return node.value;
    case "name": {
      const found = lookup(node.name);
      if (found === undefined) throw new Failed(node.at, `no value for parameter "${node.name}"`);
      return found;
    }
    case "conditional":
      return truthy(value(node.test, lookup)) ? value(node.then, lookup) : value(node.otherwise, lookup);
    case "unary": {
      const operand = value(node.operand, lookup);
      return node.op === "!" ? !truthy(operand) : finite(-number(operand, "-", node.at), node.at);
    }
    case "binary":
      return binary(node.op, node, lookup);
    case "call": {
      const args = node.args.map((a) => number(value(a, lookup), `math.${node.fn}`, node.at));
      return finite(Math[node.fn](...(args as [number])), node.at);
    }
  }
}

function binary(op: BinaryOp, node: Node & { kind: "binary" }, lookup: (name: string) => JsonValue | undefined) {
  const left = value(node.left, lookup);
  if (op === "&&") return truthy(left) ? value(node.right, lookup) : left;
  if (op === "||") return truthy(left) ? left : value(node.right, lookup);
  const right = value(node.right, lookup);
  if (op === "===") return same(left, right);
  if (op === "!==") return !same(left, right);
  if (op === "+" && typeof left === "string" && typeof right === "string") return left + right;
  const a = number(left, op, node.at);
  const b = number(right, op, node.at);
  switch (op) {
    case "<":
      return a < b;
    case "<=":
      return a <= b;
    case ">":
      return a > b;
    case ">=":
      return a >= b;
    case "+":
      return finite(a + b, node.at);
    case "-":
      return finite(a - b, node.at);
    case "*":
      return finite(a * b, node.at);
    case "/":
      return finite(a / b, node.at);
    case "%":
      return finite(a % b, node.at);
  }
}

const same = (a: JsonValue, b: JsonValue) =>
  typeof a === "object" || typeof b === "object" ? JSON.stringify(a) === JSON.stringify(b) : a === b;

function number(v: JsonValue, op: string, at: number): number {
  if (typeof v === "number") return v;
  throw new Failed(
    at,
    `"${op}" needs numbers${op === "+" ? " or two strings" : ""}, not ${JSON.stringify(v).slice(0, 40)}`,
  );
}

function finite(n: number, at: number): number {
  if (!Number.isFinite(n)) throw new Failed(at, "the result is not a finite number");
  // -0 would reach the robot as 0 anyway (JSON has no negative zero); say so here.
  return n === 0 ? 0 : n;
}
