import { describe, expect, it } from "vitest";
import { keyPress, type OpenState, type Press } from "./live";
import { schemeTemplate } from "./templates";

const engagement = schemeTemplate("participant-engagement");
const gaze = engagement.sets[0]!;
const expression = engagement.sets[1]!;
const [robot, task] = gaze.codes;
const smile = expression.codes[0]!;

describe("an observer's key press", () => {
  it.each<[string, OpenState[], Press]>([
    [
      "a point event is marked, whatever holds",
      [{ id: "o1", setId: "gaze", codeId: "robot" }],
      { end: [], start: { setId: "expression", codeId: "smile", kind: "point" } },
    ],
    [
      "a state starts when nothing of its set holds",
      [],
      { end: [], start: { setId: "gaze", codeId: "task", kind: "state" } },
    ],
    [
      "a state ends the other state of its set as it starts",
      [{ id: "o1", setId: "gaze", codeId: "robot" }],
      { end: ["o1"], start: { setId: "gaze", codeId: "task", kind: "state" } },
    ],
    ["a state's key again ends it", [{ id: "o2", setId: "gaze", codeId: "task" }], { end: ["o2"], start: null }],
    [
      "another set's state is left alone",
      [{ id: "o3", setId: "posture", codeId: "lean" }],
      { end: [], start: { setId: "gaze", codeId: "task", kind: "state" } },
    ],
  ])("%s", (name, open, press) => {
    const [set, code] = name.startsWith("a point") ? [expression, smile] : [gaze, task!];
    expect(keyPress(open, set, code)).toEqual(press);
  });

  it("pressing the held state's key ends it without starting it again", () => {
    expect(keyPress([{ id: "o1", setId: "gaze", codeId: "robot" }], gaze, robot!)).toEqual({
      end: ["o1"],
      start: null,
    });
  });
});
