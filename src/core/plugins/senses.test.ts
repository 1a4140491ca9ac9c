// Event conditions as tables: sequences of messages in the shapes the robots
// publish them (naoqi_bridge_msgs' HeadTouch and WordRecognized,
// sensor_msgs' Range), each with its time, and which of them are events.
import { describe, expect, it } from "vitest";
import { messageTime, type SenseState, sense, UNSENSED } from "./senses";
import type { Condition, RobotEvent } from "./types";

const event = (when: Condition): RobotEvent => ({
  id: "it",
  name: "It",
  topic: "/t",
  messageType: "std_msgs/msg/Empty",
  when,
});

/** The indexes of the messages that were events, fed in order from the start state. */
function fired(when: Condition, messages: Array<[number, unknown]>): number[] {
  let state: SenseState = UNSENSED;
  const out: number[] = [];
  messages.forEach(([at, message], i) => {
    const step = sense(event(when), state, message, at);
    state = step.state;
    if (step.sensed) out.push(i);
  });
  return out;
}

const middle: Condition = { kind: "pressed", field: "state", equals: 1, where: { button: 2 } };
const touch = (button: number, state: number) => ({ button, state });

describe("a touch sensor pressed", () => {
  it.each<[string, Array<[number, unknown]>, number[]]>([
    [
      "pressed then released: one event, on the press",
      [
        [0, touch(2, 1)],
        [400, touch(2, 0)],
      ],
      [0],
    ],
    [
      "held (the press said again): still one",
      [
        [0, touch(2, 1)],
        [100, touch(2, 1)],
        [200, touch(2, 1)],
      ],
      [0],
    ],
    ["a release alone: none", [[0, touch(2, 0)]], []],
    [
      "pressed twice: two",
      [
        [0, touch(2, 1)],
        [300, touch(2, 0)],
        [600, touch(2, 1)],
        [900, touch(2, 0)],
      ],
      [0, 2],
    ],
    [
      "another button: none",
      [
        [0, touch(1, 1)],
        [100, touch(3, 1)],
      ],
      [],
    ],
    [
      "another button released while this one is held: no second",
      [
        [0, touch(2, 1)],
        [50, touch(1, 1)],
        [100, touch(1, 0)],
        [150, touch(2, 1)],
      ],
      [0],
    ],
  ])("%s", (_what, messages, expected) => {
    expect(fired(middle, messages)).toEqual(expected);
  });
});

const ready: Condition = {
  kind: "heard",
  field: "words",
  confidenceField: "confidence_values",
  words: ["ready", "let's go"],
  minConfidence: 0.5,
};
const words = (pairs: Array<[string, number]>) => ({
  words: pairs.map(([w]) => w),
  confidence_values: pairs.map(([, c]) => c),
});

describe("a recognised word", () => {
  it.each<[string, unknown, boolean]>([
    ["above the threshold", words([["ready", 0.62]]), true],
    ["at the threshold", words([["ready", 0.5]]), true],
    ["below the threshold", words([["ready", 0.41]]), false],
    ["in another case, with spaces", words([[" Let's Go ", 0.9]]), true],
    ["another word", words([["hello", 0.95]]), false],
    [
      "among others, its own confidence counts",
      words([
        ["hello", 0.9],
        ["ready", 0.3],
      ]),
      false,
    ],
    [
      "the second of two, above",
      words([
        ["hello", 0.2],
        ["ready", 0.7],
      ]),
      true,
    ],
    ["nothing heard", words([]), false],
    ["a word without its confidence", { words: ["ready"], confidence_values: [] }, false],
  ])("%s", (_what, message, expected) => {
    expect(fired(ready, [[0, message]])).toEqual(expected ? [0] : []);
  });

  it("each recognition is its own event", () => {
    expect(
      fired(ready, [
        [0, words([["ready", 0.8]])],
        [2000, words([["ready", 0.8]])],
      ]),
    ).toEqual([0, 1]);
  });
});

const close: Condition = { kind: "near", field: "range", below: 0.5, forMs: 500, clearAbove: 0.7 };
/** A sonar's sensor_msgs/Range every 100 ms, the distances given. */
const sonar = (ranges: Array<number | null>): Array<[number, unknown]> =>
  ranges.map((range, i) => [
    i * 100,
    {
      header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "LSonar_frame" },
      radiation_type: 0,
      field_of_view: 1.05,
      min_range: 0.25,
      max_range: 2.55,
      range,
    },
  ]);

describe("a distance under a threshold for a time", () => {
  it.each<[string, Array<number | null>, number[]]>([
    ["far all along: none", [1.2, 1.1, 1.0, 0.9], []],
    ["close for less than the time: none", [1.0, 0.4, 0.4, 0.4, 0.8, 1.0], []],
    ["close for the time: one, when the time is up", [1.0, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4], [6]],
    [
      "flapping around the threshold: one",
      [1.0, 0.45, 0.52, 0.48, 0.55, 0.49, 0.51, 0.47, 0.53, 0.46, 0.54, 0.48],
      [7],
    ],
    ["staying close: still one", [0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3], [5]],
    ["close, clear, close again: two", [0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 1.0, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3], [5, 12]],
    [
      "close, not quite clear, close again: one",
      [0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.65, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3],
      [5],
    ],
    ["out of range (null, rosbridge's infinity) clears", [0.3, 0.3, 0.3, null, 0.3, 0.3, 0.3], []],
  ])("%s", (_what, ranges, expected) => {
    expect(fired(close, sonar(ranges))).toEqual(expected);
  });

  it("a laser scan's nearest reading counts; its 0s and nulls are no return", () => {
    const scan = { kind: "near", field: "ranges", below: 0.3, forMs: 0, clearAbove: 0.4 } as const;
    expect(
      fired(scan, [
        [0, { ranges: [0, null, 1.2, 0.9] }],
        [100, { ranges: [0, 2, 0.25, null] }],
      ]),
    ).toEqual([1]);
  });
});

describe("what a sensed event carries", () => {
  it("its id, the time given and the message", () => {
    const message = touch(2, 1);
    expect(sense(event(middle), UNSENSED, message, 1234).sensed).toEqual({ event: "it", at: 1234, message });
  });

  it.each<[string, unknown, number]>([
    [
      "a header stamp: the robot's time",
      { header: { stamp: { sec: 1_700_000_000, nanosec: 250_000_000 } } },
      1_700_000_000_250,
    ],
    ["no header: the runtime's", { button: 2, state: 1 }, 42],
    ["a zero stamp (unset): the runtime's", { header: { stamp: { sec: 0, nanosec: 0 } } }, 42],
  ])("time of a message with %s", (_what, message, expected) => {
    expect(messageTime(message, 42)).toBe(expected);
  });
});
