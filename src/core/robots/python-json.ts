// JSON as Python writes and reads it: rosbridge (Python's json, or ujson)
// writes NaN, Infinity and -Infinity as bare literals, which JSON.parse
// refuses. Outside strings they are swapped for marker strings and turned
// back into numbers once parsed.
const LITERAL = /"(?:[^"\\]|\\.)*"|-?Infinity|NaN/g;
const MARK = "\u0000hri-float:";
const NUMBERS: Record<string, number> = {
  NaN: Number.NaN,
  Infinity: Number.POSITIVE_INFINITY,
  "-Infinity": Number.NEGATIVE_INFINITY,
};

export function parsePythonJson(text: string): unknown {
  if (!/NaN|Infinity/.test(text)) return JSON.parse(text);
  const marked = text.replace(LITERAL, (token) => (token.startsWith('"') ? token : JSON.stringify(MARK + token)));
  return JSON.parse(marked, (_key, value) =>
    typeof value === "string" && value.startsWith(MARK) ? NUMBERS[value.slice(MARK.length)] : value,
  );
}
