// How the server writes frames, as the recorded rosbridge does (README G3):
// ujson escapes "/" as "\/" and every non-ASCII character as \uXXXX, so frames
// are pure ASCII; key order is the server's. Parsed values are plain JSON.
// Large frames are split into fragments when the connection has a fragment
// size, with rosbridge's float "total" ((length - 1) / size + 1).

export function encode(value: unknown): string {
  return escaped(JSON.stringify(value));
}

/** A publish frame whose message is already JSON text (typed: floats keep ".0", see messageJson). */
export function encodePublish(topic: string, msgJson: string): string {
  return escaped(`{"op":"publish","topic":${JSON.stringify(topic)},"msg":${msgJson}}`);
}

const escaped = (json: string) =>
  json.replace(/[/\u0080-\uffff]/g, (c) => (c === "/" ? "\\/" : `\\u${c.charCodeAt(0).toString(16).padStart(4, "0")}`));

export function fragments(text: string, size: number, id: unknown): string[] {
  if (text.length <= size) return [text];
  const total = (text.length - 1) / size + 1;
  const out: string[] = [];
  for (let num = 0, cursor = 0; cursor < text.length; num++, cursor += size) {
    out.push(encode({ op: "fragment", id: id ?? 0, data: text.slice(cursor, cursor + size), num, total }));
  }
  return out;
}
