// The loader refuses an event it could not watch, with a reason naming the
// event: a templated topic, a message type whose fields we do not know, a
// condition on a field the message lacks or of the wrong kind, a taken id.
import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { checkDocument } from "./load";
import type { RobotEvent } from "./types";

const base = JSON.parse(readFileSync("tests/fixtures/plugins/base.json", "utf8")) as Record<string, unknown>;
const headTouched: RobotEvent = {
  id: "head_touched",
  name: "Head touched",
  topic: "/head_touch",
  messageType: "naoqi_bridge_msgs/msg/HeadTouch",
  when: { kind: "pressed", field: "state", equals: 1, where: { button: 2 } },
};
const heard: RobotEvent = {
  id: "heard_ready",
  name: "Heard ready",
  topic: "/word_recognized",
  messageType: "naoqi_bridge_msgs/msg/WordRecognized",
  when: { kind: "heard", field: "words", confidenceField: "confidence_values", words: ["ready"], minConfidence: 0.5 },
};
const near: RobotEvent = {
  id: "someone_close",
  name: "Someone close",
  topic: "/sonar/left",
  messageType: "sensor_msgs/msg/Range",
  when: { kind: "near", field: "range", below: 0.5, forMs: 500, clearAbove: 0.7 },
};

const errorsOf = (events: unknown[]) => {
  const result = checkDocument("robot.json", { ...base, events });
  return result.ok ? [] : result.errors.map((e) => ({ code: e.code, path: e.path, reason: e.reason }));
};

describe("a plugin's events, checked at load", () => {
  it("sound events load", () => {
    expect(errorsOf([headTouched, heard, near])).toEqual([]);
  });

  it.each<[string, unknown, string, string]>([
    [
      "a templated topic",
      { ...headTouched, topic: "/naoqi_driver/{part}_touch" },
      "/events/0/topic",
      'event "head_touched": its topic /naoqi_driver/{part}_touch has {parameter} parts, but nothing fills an event\'s topic: name one topic',
    ],
    [
      "a message type whose shape is unknown",
      { ...headTouched, messageType: "acme_msgs/msg/Tickle" },
      "/events/0/messageType",
      'event "head_touched": HRIStudio does not know the fields of acme_msgs/msg/Tickle, so its condition cannot be checked',
    ],
    [
      "a field the message lacks",
      { ...headTouched, when: { kind: "pressed", field: "pressed", equals: 1 } },
      "/events/0/when/field",
      'event "head_touched": naoqi_bridge_msgs/msg/HeadTouch has no field pressed',
    ],
    [
      "a value of the wrong kind",
      { ...headTouched, when: { kind: "pressed", field: "state", equals: "pressed" } },
      "/events/0/when/field",
      'event "head_touched": state of naoqi_bridge_msgs/msg/HeadTouch is uint8, not a field "pressed" can be compared with',
    ],
    [
      "a where field the message lacks",
      { ...headTouched, when: { kind: "pressed", field: "state", equals: 1, where: { hand: 2 } } },
      "/events/0/when/where/hand",
      'event "head_touched": naoqi_bridge_msgs/msg/HeadTouch has no field hand',
    ],
    [
      "words read from numbers",
      { ...heard, when: { ...heard.when, field: "confidence_values" } },
      "/events/0/when/field",
      'event "heard_ready": confidence_values of naoqi_bridge_msgs/msg/WordRecognized is float32[], not words (string or string[])',
    ],
    [
      "a distance that is text",
      { ...near, messageType: "std_msgs/msg/String", when: { ...near.when, field: "data" } },
      "/events/0/when/field",
      'event "someone_close": data of std_msgs/msg/String is string, not a distance (a number or a list of them)',
    ],
    [
      "a clear distance under the near one",
      { ...near, when: { ...near.when, clearAbove: 0.3 } },
      "/events/0/when/clearAbove",
      'event "someone_close": clearAbove (0.3) is less than below (0.5): nothing near would ever clear',
    ],
  ])("%s is refused, naming the event", (_what, event, path, reason) => {
    expect(errorsOf([event])).toEqual([{ code: "bad_event", path, reason }]);
  });

  it("a taken id is refused", () => {
    expect(errorsOf([headTouched, { ...near, id: "head_touched" }])).toEqual([
      { code: "bad_event", path: "/events/1/id", reason: 'event "head_touched": the id is already used by /events/0' },
    ]);
  });

  it.each<[string, unknown, Array<[string, string]>]>([
    [
      "a condition missing its kind's fields",
      { kind: "heard", words: ["ready"] },
      [
        ["/events/0/when/field", "is required but missing"],
        ["/events/0/when/confidenceField", "is required but missing"],
        ["/events/0/when/minConfidence", "is required but missing"],
      ],
    ],
    [
      "a condition of no known kind",
      { kind: "smelled" },
      [["/events/0/when/kind", 'must be one of: "pressed", "heard", "near"']],
    ],
    [
      "another kind's field",
      { kind: "near", field: "range", below: 0.5, forMs: 500, clearAbove: 0.7, equals: 1 },
      [["/events/0/when/equals", "is not an allowed field here"]],
    ],
  ])("%s is the schema's error, at its place", (_what, when, expected) => {
    expect(errorsOf([{ ...heard, when }])).toEqual(
      expected.map(([path, reason]) => ({ code: "schema", path, reason })),
    );
  });
});
