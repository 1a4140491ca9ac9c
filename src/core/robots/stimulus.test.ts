// The messages a simulated stimulus becomes, by kind of condition, and that
// each one is an event by the condition it was built from (senses.ts).
import { describe, expect, it } from "vitest";
import { sense, UNSENSED } from "../plugins/senses";
import type { RobotEvent } from "../plugins/types";
import { distanceMessage, distanceOf, heardMessage, touchMessages } from "./stimulus";

const event = (messageType: string, when: RobotEvent["when"]): RobotEvent => ({
  id: "e",
  name: "E",
  topic: "/t",
  messageType,
  when,
});
const head = event("naoqi_bridge_msgs/msg/HeadTouch", {
  kind: "pressed",
  field: "state",
  equals: 1,
  where: { button: 2 },
});
const bumper = event("turtlebot3_msgs/msg/SensorState", { kind: "pressed", field: "bumper", equals: 2 });
const flag = event("std_msgs/msg/Bool", { kind: "pressed", field: "data", equals: true });
const words = event("naoqi_bridge_msgs/msg/WordRecognized", {
  kind: "heard",
  field: "words",
  confidenceField: "confidence_values",
  words: ["ready"],
  minConfidence: 0.5,
});
const sonar = event("sensor_msgs/msg/Range", { kind: "near", field: "range", below: 0.5, forMs: 0, clearAbove: 0.7 });
const laser = event("sensor_msgs/msg/LaserScan", {
  kind: "near",
  field: "ranges",
  below: 0.3,
  forMs: 0,
  clearAbove: 0.45,
});

describe("a touch", () => {
  it.each<[string, RobotEvent, unknown, unknown]>([
    ["a head sensor", head, { button: 2, state: 1 }, { button: 2, state: 0 }],
    ["a bumper value", bumper, { bumper: 2 }, { bumper: 0 }],
    ["a flag", flag, { data: true }, { data: false }],
  ])("%s: pressed, then released", (_what, e, pressed, released) => {
    const messages = touchMessages(e);
    expect(messages).toEqual({ pressed, released });
    const press = sense(e, UNSENSED, messages.pressed, 0);
    expect(press.sensed).not.toBeNull();
    expect(sense(e, press.state, messages.released, 300).sensed).toBeNull();
  });
});

describe("a phrase heard", () => {
  it.each<[number, boolean]>([
    [0.8, true],
    [0.3, false],
  ])("with confidence %s: an event %s", (confidence, heard) => {
    const message = heardMessage(words, "ready", confidence);
    expect(message).toEqual({ words: ["ready"], confidence_values: [confidence] });
    expect(sense(words, UNSENSED, message, 0).sensed !== null).toBe(heard);
  });
});

describe("someone close", () => {
  it.each<[string, RobotEvent, unknown, unknown]>([
    ["a sonar", sonar, { range: 0.25 }, { range: 1.4 }],
    ["a laser's one reading", laser, { ranges: [0.15] }, { ranges: [0.9] }],
  ])("%s: close is an event, away is not", (_what, e, close, away) => {
    expect(distanceMessage(e, distanceOf(e, true))).toEqual(close);
    expect(distanceMessage(e, distanceOf(e, false))).toEqual(away);
    expect(sense(e, UNSENSED, close, 0).sensed).not.toBeNull();
    expect(sense(e, UNSENSED, away, 0).sensed).toBeNull();
  });
});
