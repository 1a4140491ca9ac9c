// Reading a large experiment file a piece at a time. JSON.parse of a 2 MB
// file holds the server for tens of milliseconds in one go; the file's steps
// are instead found by a scan that yields as it goes, and parsed one by one.
// The result is what JSON.parse gives; anything unusual (a file that is not an
// object, "steps" named twice, bad JSON) is parsed whole, as before, so its
// problem is reported exactly as it always was.
import { type ParsedJson, parseJsonText } from "../plugins/json-text";
import type { Work } from "../work";

/** Below this a file is parsed whole: a few milliseconds at most. */
const WHOLE = 256 * 1024;
/** Characters scanned between yields. */
const SCAN = 64 * 1024;

const QUOTE = 34;
const BACKSLASH = 92;
const COLON = 58;
const COMMA = 44;
const BRACE = 123;
const BRACKET = 91;
const CLOSING_BRACE = 125;
const CLOSING_BRACKET = 93;

export function* parsingFile(text: string): Work<ParsedJson> {
  const split = text.length < WHOLE ? null : yield* stepsOf(text);
  if (!split) return parseJsonText(text);
  try {
    const envelope = JSON.parse(`${text.slice(0, split.start)}[]${text.slice(split.end)}`) as Record<string, unknown>;
    const steps: unknown[] = [];
    for (const [from, to] of split.elements) {
      steps.push(JSON.parse(text.slice(from, to)));
      yield;
    }
    envelope.steps = steps;
    return { ok: true, value: envelope };
  } catch {
    return parseJsonText(text);
  }
}

interface Split {
  /** Where the root's "steps" list starts ("[") and ends (after "]"). */
  start: number;
  end: number;
  /** Each element of the list, [from, to) in the text. */
  elements: Array<[number, number]>;
}

/** Where the root object's "steps" list and its elements are, or null for anything unusual. */
function* stepsOf(text: string): Work<Split | null> {
  let depth = 0;
  let stringAt = -1;
  let lastString = "";
  let key = "";
  let split: Split | null = null;
  let inSteps = false;
  let elementAt = -1;
  const element = (end: number) => text.slice(elementAt, end).trim() !== "";
  for (let i = 0; i < text.length; i++) {
    if (i % SCAN === 0 && i > 0) yield;
    const c = text.charCodeAt(i);
    if (stringAt >= 0) {
      if (c === BACKSLASH) i++;
      else if (c === QUOTE) {
        if (depth === 1) lastString = text.slice(stringAt, i + 1);
        stringAt = -1;
      }
      continue;
    }
    switch (c) {
      case QUOTE:
        stringAt = i;
        break;
      case COLON:
        // A key written with escapes may name "steps" without looking like it.
        if (depth === 1 && lastString.includes("\\")) return null;
        if (depth === 1) key = lastString;
        break;
      case BRACE:
      case BRACKET:
        if (depth === 0 && c !== BRACE) return null;
        depth++;
        if (depth === 2 && c === BRACKET && key === '"steps"') {
          if (split) return null; // named twice: JSON.parse keeps the last
          split = { start: i, end: -1, elements: [] };
          inSteps = true;
          elementAt = i + 1;
        }
        break;
      case CLOSING_BRACE:
      case CLOSING_BRACKET:
        if (depth === 2 && inSteps) {
          if (element(i)) split!.elements.push([elementAt, i]);
          else if (split!.elements.length) return null; // a comma before "]"
          split!.end = i + 1;
          inSteps = false;
        }
        depth--;
        break;
      case COMMA:
        if (depth === 1) key = "";
        if (depth !== 2 || !inSteps) break;
        if (!element(i)) return null;
        split!.elements.push([elementAt, i]);
        elementAt = i + 1;
        break;
    }
  }
  return split && split.end > 0 && depth === 0 ? split : null;
}
