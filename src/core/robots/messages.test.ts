// The message shapes the loader reads: a field's type by dotted path, in
// either spelling of a type, and nothing for what a message does not have.
import { describe, expect, it } from "vitest";
import { fieldType, knownMessage, messageKey } from "./messages";

describe("message shapes", () => {
  it.each<[string, string, string | null]>([
    ["naoqi_bridge_msgs/msg/HeadTouch", "state", "uint8"],
    ["naoqi_bridge_msgs/HeadTouch", "button", "uint8"],
    ["naoqi_bridge_msgs/msg/WordRecognized", "words", "string[]"],
    ["sensor_msgs/msg/Range", "header.stamp.sec", "int32"],
    ["sensor_msgs/msg/Range", "header.stamp.minutes", null],
    ["sensor_msgs/msg/Range", "range.value", null],
    ["acme_msgs/msg/Tickle", "state", null],
    ["naoqi_bridge_msgs/srv/HeadTouch", "state", null],
  ])("%s, %s: %s", (type, path, expected) => {
    expect(fieldType(type, path)).toBe(expected);
  });

  it.each<[string, string | null, boolean]>([
    ["sensor_msgs/msg/LaserScan", "sensor_msgs/LaserScan", true],
    ["turtlebot3_msgs/SensorState", "turtlebot3_msgs/SensorState", true],
    ["acme_msgs/msg/Tickle", "acme_msgs/Tickle", false],
    ["std_msgs/msg/String/extra", null, false],
    ["String", null, false],
  ])("%s: key %s, known %s", (type, key, known) => {
    expect(messageKey(type)).toBe(key);
    expect(knownMessage(type)).toBe(known);
  });
});
