// Canonical JSON (keys sorted, no whitespace) and its SHA-256: the identity
// of a published protocol version. The same design always hashes the same.
// It is written by a walk that keeps its own list of the lists and objects
// it is inside, not by recursion, and comes out in pieces: no depth overflows
// the stack, and a design of 50,000 actions is hashed a slice at a time.
import { createHash } from "node:crypto";
import { finish, type Work } from "../work";

/** Text handed out at a time: a few hundred actions of a design. */
const PIECE = 64 * 1024;

/** A list, or an object's entries, being written, and how many of them are written. */
type Open = { list: unknown[]; entries?: never; next: number } | { entries: [string, unknown][]; next: number };

export function canonicalJson(value: unknown): string {
  const pieces: string[] = [];
  for (const piece of canonicalPieces(value)) pieces.push(piece);
  return pieces.join("");
}

/** The canonical text of `value`, in pieces of about 64 KB. */
export function* canonicalPieces(value: unknown): Generator<string, void, void> {
  const piece = writer(value);
  for (let text = piece(); text !== null; text = piece()) yield text;
}

/** Each call writes the next piece of the text; null once it is all written. */
function writer(value: unknown): () => string | null {
  const open: Open[] = [];
  let out = "";
  const write = (item: unknown) => {
    if (item === null || typeof item === "boolean" || typeof item === "string") out += JSON.stringify(item);
    else if (typeof item === "number") {
      if (!Number.isFinite(item)) throw new Error(`${where(open)}: ${item} cannot be stored as JSON`);
      out += JSON.stringify(item);
    } else if (Array.isArray(item)) {
      out += "[";
      open.push({ list: item, next: 0 });
    } else if (typeof item === "object") {
      const entries = Object.entries(item as Record<string, unknown>)
        .filter(([, v]) => v !== undefined)
        .sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0));
      out += "{";
      open.push({ entries, next: 0 });
    } else throw new Error(`${where(open)}: a ${typeof item} cannot be stored as JSON`);
  };
  let started = false;
  return () => {
    if (!started) {
      started = true;
      write(value);
    } else if (!open.length) return null;
    while (open.length && out.length < PIECE) {
      const top = open[open.length - 1]!;
      const next = top.next++;
      if (top.entries) {
        if (next === top.entries.length) {
          out += "}";
          open.pop();
        } else {
          const [key, item] = top.entries[next]!;
          out += next > 0 ? `,${JSON.stringify(key)}:` : `${JSON.stringify(key)}:`;
          write(item);
        }
      } else if (next === top.list.length) {
        out += "]";
        open.pop();
      } else {
        if (next > 0) out += ",";
        write(top.list[next]);
      }
    }
    const piece = out;
    out = "";
    return piece;
  };
}

/** The path of the value being written, e.g. $.steps[0].seconds. */
function where(open: Open[]): string {
  return open.reduce((path, o) => (o.entries ? `${path}.${o.entries[o.next - 1]![0]}` : `${path}[${o.next - 1}]`), "$");
}

export function sha256Hex(text: string): string {
  return createHash("sha256").update(text, "utf8").digest("hex");
}

export function hashCanonical(value: unknown): string {
  return finish(hashing(value)).hash;
}

/** The canonical text and its hash, as work that yields after each piece, for the server to run in slices. */
export function* hashing(value: unknown): Work<{ text: string; hash: string }> {
  const hash = createHash("sha256");
  const pieces: string[] = [];
  for (const piece of canonicalPieces(value)) {
    hash.update(piece, "utf8");
    pieces.push(piece);
    yield;
  }
  return { text: pieces.join(""), hash: hash.digest("hex") };
}
