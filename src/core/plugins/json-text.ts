// JSON.parse says "invalid" but not reliably where (V8's messages vary and
// often omit the position). When it fails we rescan with a small strict
// scanner whose only job is to find the first bad character, so a researcher
// who edited a plugin by hand is told the line and column. For a plugin file,
// one loop first counts how deep its lists and objects go (tooDeep): a file
// nested deeper than MAX_DEPTH is refused before anything is built from it,
// so nothing after (schema checks, placeholders, hashing) can be made to
// recurse deeper. An experiment file has its own, lower bound (exchange.ts).

export type ParsedJson = { ok: true; value: unknown } | { ok: false; line: number; column: number; reason: string };

/** How deep lists and objects may nest in a file we read. HRIStudio's files and ours go 7 levels. */
export const MAX_DEPTH = 256;

export function parseJsonText(text: string): ParsedJson {
  try {
    return { ok: true, value: JSON.parse(text) };
  } catch {
    const { offset, reason } = findSyntaxError(text.charCodeAt(0) === 0xfeff ? text.slice(1) : text);
    const skip = text.charCodeAt(0) === 0xfeff ? 1 : 0;
    return { ok: false, ...lineAndColumn(text, offset + skip), reason };
  }
}

function lineAndColumn(text: string, offset: number) {
  const before = text.slice(0, offset);
  const line = before.split("\n").length;
  return { line, column: offset - before.lastIndexOf("\n") };
}

/** The reason a file nested deeper than MAX_DEPTH is refused. */
export const nestedTooDeep = `nested more than ${MAX_DEPTH} levels deep (lists and objects inside each other), the limit for a file`;

/** Where the first list or object deeper than MAX_DEPTH opens, or null when none is. */
export function tooDeep(text: string): { line: number; column: number } | null {
  const at = tooDeepAt(text);
  return at === null ? null : lineAndColumn(text, at);
}

/** The offset of the first list or object deeper than MAX_DEPTH, or null. Strings are skipped, escapes and all. */
function tooDeepAt(text: string): number | null {
  let depth = 0;
  let inString = false;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (inString) {
      if (c === 0x5c) i++;
      else if (c === 0x22) inString = false;
    } else if (c === 0x22) inString = true;
    else if (c === 0x5b || c === 0x7b) {
      if (++depth > MAX_DEPTH) return i;
    } else if (c === 0x5d || c === 0x7d) depth--;
  }
  return null;
}

class Stop {
  constructor(
    readonly offset: number,
    readonly reason: string,
  ) {}
}

function findSyntaxError(text: string): { offset: number; reason: string } {
  let i = 0;
  let depth = 0;
  const fail = (reason: string): never => {
    throw new Stop(i, reason);
  };
  const describe = () => (i >= text.length ? "the end of the file" : JSON.stringify(text[i]));
  const space = () => {
    while (i < text.length && " \t\n\r".includes(text[i]!)) i++;
  };
  const literal = (word: string) => {
    if (text.startsWith(word, i)) i += word.length;
    else fail(`unexpected ${describe()}`);
  };
  const string = () => {
    i++;
    while (i < text.length && text[i] !== '"') {
      const c = text.charCodeAt(i);
      if (c < 0x20) fail("a control character (such as a raw line break) inside a string; write it as \\n");
      if (text[i] === "\\") {
        i++;
        if (text[i] === "u") {
          if (!/^[0-9a-fA-F]{4}$/.test(text.slice(i + 1, i + 5))) fail("a \\u escape needs four hex digits");
          i += 4;
        } else if (!'"\\/bfnrt'.includes(text[i] ?? "")) fail(`invalid escape \\${text[i] ?? ""}`);
      }
      i++;
    }
    if (i >= text.length) fail("a string is not closed");
    i++;
  };
  const number = () => {
    const match = /^-?(0|[1-9]\d*)(\.\d+)?([eE][+-]?\d+)?/.exec(text.slice(i));
    if (!match) fail(`unexpected ${describe()}`);
    i += match![0].length;
  };
  const value = (): void => {
    space();
    if (++depth > MAX_DEPTH) fail(`nested more than ${MAX_DEPTH} levels deep`);
    try {
      container();
    } finally {
      depth--;
    }
  };
  const container = () => {
    const c = text[i];
    if (c === "{") return object();
    if (c === "[") return array();
    if (c === '"') return string();
    if (c === "t") return literal("true");
    if (c === "f") return literal("false");
    if (c === "n") return literal("null");
    if (c === "-" || (c !== undefined && c >= "0" && c <= "9")) return number();
    fail(
      i >= text.length
        ? "the file ends where a value was expected"
        : `unexpected ${describe()} where a value was expected`,
    );
  };
  const object = () => {
    i++;
    space();
    if (text[i] === "}") return void i++;
    for (;;) {
      space();
      if (text[i] !== '"') fail(`expected a quoted property name, found ${describe()}`);
      string();
      space();
      if (text[i] !== ":") fail(`expected ":" after a property name, found ${describe()}`);
      i++;
      value();
      space();
      if (text[i] === ",") {
        i++;
        continue;
      }
      if (text[i] === "}") return void i++;
      fail(`expected "," or "}" in an object, found ${describe()}`);
    }
  };
  const array = () => {
    i++;
    space();
    if (text[i] === "]") return void i++;
    for (;;) {
      value();
      space();
      if (text[i] === ",") {
        i++;
        continue;
      }
      if (text[i] === "]") return void i++;
      fail(`expected "," or "]" in a list, found ${describe()}`);
    }
  };
  try {
    value();
    space();
    if (i < text.length) fail(`unexpected ${describe()} after the end of the document`);
    return { offset: 0, reason: "invalid JSON" };
  } catch (stop) {
    if (stop instanceof Stop) return { offset: stop.offset, reason: stop.reason };
    throw stop;
  }
}
