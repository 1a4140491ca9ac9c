// The expressions a template may hold inside {{ }}: parsed into a tree by a
// small recursive-descent parser, never run as JavaScript (no eval, no
// Function), so a plugin file can compute a value but reach nothing. The
// grammar is in docs/plugins.md ("Expressions"); evaluate.ts gives the values.

export type Node =
  | { kind: "literal"; value: string | number | boolean | null }
  | { kind: "name"; name: string; at: number }
  | { kind: "unary"; op: "!" | "-"; operand: Node; at: number }
  | { kind: "binary"; op: BinaryOp; left: Node; right: Node; at: number }
  | { kind: "conditional"; test: Node; then: Node; otherwise: Node }
  | { kind: "call"; fn: MathFn; args: Node[]; at: number };

export type BinaryOp = "||" | "&&" | "===" | "!==" | "<" | "<=" | ">" | ">=" | "+" | "-" | "*" | "/" | "%";
export const MATH_FNS = ["round", "floor", "ceil", "min", "max", "abs"] as const;
export type MathFn = (typeof MATH_FNS)[number];

/** Deeper nesting than this (brackets, `? :`, `!`, `-`) is refused: a file cannot exhaust the stack. */
export const MAX_NESTING = 32;
/** A longer expression is refused before it is read. */
export const MAX_LENGTH = 1000;

/** `at` is the 0-based character offset in the expression text where the parser stopped. */
export type Parsed = { ok: true; node: Node } | { ok: false; at: number; reason: string };

const TOKEN =
  /\s*(?:(\d+(?:\.\d+)?(?:[eE][+-]?\d+)?)|('(?:[^'\\]|\\.)*'|"(?:[^"\\]|\\.)*")|([A-Za-z_][A-Za-z0-9_]*)|(===|!==|==|!=|<=|>=|&&|\|\||[-+*/%<>!?:(),.]))/y;

type Token = { text: string; type: "number" | "string" | "word" | "op" | "end"; at: number };

class Refused extends Error {
  constructor(
    readonly at: number,
    reason: string,
  ) {
    super(reason);
  }
}

export function parseExpression(text: string): Parsed {
  if (text.length > MAX_LENGTH) return { ok: false, at: 0, reason: `longer than ${MAX_LENGTH} characters` };
  try {
    const parser = new Parser(tokens(text));
    const node = parser.conditional(0);
    parser.expectEnd();
    return { ok: true, node };
  } catch (error) {
    if (error instanceof Refused) return { ok: false, at: error.at, reason: error.message };
    throw error;
  }
}

/** The parameter names an expression reads. */
export function namesIn(node: Node): string[] {
  switch (node.kind) {
    case "literal":
      return [];
    case "name":
      return [node.name];
    case "unary":
      return namesIn(node.operand);
    case "binary":
      return [...namesIn(node.left), ...namesIn(node.right)];
    case "conditional":
      return [...namesIn(node.test), ...namesIn(node.then), ...namesIn(node.otherwise)];
    case "call":
      return node.args.flatMap(namesIn);
  }
}

function tokens(text: string): Token[] {
  const out: Token[] = [];
  let at = 0;
  while (!/^\s*$/.test(text.slice(at))) {
    TOKEN.lastIndex = at;
    const match = TOKEN.exec(text);
    const start = at + (text.slice(at).length - text.slice(at).trimStart().length);
    if (!match) throw new Refused(start, `"${text[start]}" is not part of the expression language`);
    const [whole, number, string, word] = match;
    const type = number !== undefined ? "number" : string !== undefined ? "string" : word !== undefined ? "word" : "op";
    out.push({ text: whole.trim(), type, at: start });
    at += whole.length;
  }
  out.push({ text: "", type: "end", at: text.length });
  return out;
}

const LEVELS: Array<{ ops: string[]; aliases?: Record<string, BinaryOp> }> = [
  { ops: ["||"] },
  { ops: ["&&"] },
  // == and != mean === and !==: there is no loose equality.
  { ops: ["===", "!==", "==", "!="], aliases: { "==": "===", "!=": "!==" } },
  { ops: ["<", "<=", ">", ">="] },
  { ops: ["+", "-"] },
  { ops: ["*", "/", "%"] },
];

class Parser {
  private i = 0;
  constructor(private readonly list: Token[]) {}

  private get next() {
    return this.list[this.i]!;
  }

  private take(text: string): boolean {
    if (this.next.type !== "op" || this.next.text !== text) return false;
    this.i++;
    return true;
  }

  private expect(text: string) {
    if (!this.take(text)) throw new Refused(this.next.at, `expected "${text}" but found ${shown(this.next)}`);
  }

  expectEnd() {
    if (this.next.type !== "end") throw new Refused(this.next.at, `unexpected ${shown(this.next)}`);
  }

  private deeper(depth: number, at: number) {
    if (depth >= MAX_NESTING) throw new Refused(at, `nested more than ${MAX_NESTING} levels deep`);
    return depth + 1;
  }

  conditional(depth: number): Node {
    const test = this.binary(0, depth);
    const at = this.next.at;
    if (!this.take("?")) return test;
    const inner = this.deeper(depth, at);
    const then = this.conditional(inner);
    this.expect(":");
    return { kind: "conditional", test, then, otherwise: this.conditional(inner) };
  }

  private binary(level: number, depth: number): Node {
    if (level === LEVELS.length) return this.unary(depth);
    const { ops, aliases } = LEVELS[level]!;
    let left = this.binary(level + 1, depth);
    for (;;) {
      const token = this.next;
      if (token.type !== "op" || !ops.includes(token.text)) return left;
      this.i++;
      const op = (aliases?.[token.text] ?? token.text) as BinaryOp;
      left = { kind: "binary", op, left, right: this.binary(level + 1, depth), at: token.at };
    }
  }

  private unary(depth: number): Node {
    const token = this.next;
    if (token.type === "op" && (token.text === "!" || token.text === "-")) {
      this.i++;
      const operand = this.unary(this.deeper(depth, token.at));
      return { kind: "unary", op: token.text, operand, at: token.at };
    }
    return this.primary(depth);
  }

  private primary(depth: number): Node {
    const token = this.next;
    this.i++;
    if (token.type === "number") return { kind: "literal", value: Number(token.text) };
    if (token.type === "string") return { kind: "literal", value: unquote(token.text) };
    if (token.type === "op" && token.text === "(") {
      const node = this.conditional(this.deeper(depth, token.at));
      this.expect(")");
      return node;
    }
    if (token.type === "word") {
      if (token.text === "true" || token.text === "false") return { kind: "literal", value: token.text === "true" };
      if (token.text === "null") return { kind: "literal", value: null };
      if (token.text === "math") return this.call(token.at, depth);
      return { kind: "name", name: token.text, at: token.at };
    }
    throw new Refused(token.at, `expected a value but found ${shown(token)}`);
  }

  private call(at: number, depth: number): Node {
    this.expect(".");
    const fn = this.next;
    if (fn.type !== "word" || !(MATH_FNS as readonly string[]).includes(fn.text))
      throw new Refused(fn.at, `math has ${MATH_FNS.join(", ")}, not ${shown(fn)}`);
    this.i++;
    this.expect("(");
    const inner = this.deeper(depth, at);
    const args: Node[] = [];
    if (!this.take(")")) {
      do args.push(this.conditional(inner));
      while (this.take(","));
      this.expect(")");
    }
    const arity = fn.text === "min" || fn.text === "max" ? args.length >= 1 : args.length === 1;
    if (!arity)
      throw new Refused(
        fn.at,
        `math.${fn.text} takes ${fn.text === "min" || fn.text === "max" ? "one value or more" : "one value"}`,
      );
    return { kind: "call", fn: fn.text as MathFn, args, at };
  }
}

const shown = (token: Token) => (token.type === "end" ? "the end" : `"${token.text}"`);

const ESCAPES: Record<string, string> = { n: "\n", t: "\t", r: "\r" };

function unquote(quoted: string): string {
  return quoted.slice(1, -1).replace(/\\(.)/g, (_, c: string) => ESCAPES[c] ?? c);
}
