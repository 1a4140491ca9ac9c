// What one key press of an observer does to their own tier: a point event is
// marked; a state's key starts it (ending the state of the same set that held,
// since a set's codes exclude one another), or ends it if it already holds.
import type { Code, CodeSet } from "./scheme";

export type OpenState = { id: string; setId: string; codeId: string };

export type Press = {
  /** The observer's open states to end at this moment. */
  end: string[];
  /** The code event to begin (a point event, or a state with no end yet), or none. */
  start: { setId: string; codeId: string; kind: Code["kind"] } | null;
};

export function keyPress(open: OpenState[], set: CodeSet, code: Code): Press {
  const mark = { setId: set.id, codeId: code.id, kind: code.kind };
  if (code.kind === "point") return { end: [], start: mark };
  const ofSet = open.filter((o) => o.setId === set.id);
  if (ofSet.some((o) => o.codeId === code.id)) return { end: ofSet.map((o) => o.id), start: null };
  return { end: ofSet.map((o) => o.id), start: mark };
}
