import { describe, expect, it } from "vitest";
import type { StoredEvent } from "@/core/trial";
import { logOf, nanosecondsAt, plottable, sampleSchemaName, schemaOf } from "./mcap-messages";

describe("schemaOf", () => {
  it.each([
    ["no message", [], { type: "object" }],
    ["numbers stay numbers", [{ x: 1.5 }], { type: "object", properties: { x: { type: "number" } } }],
    [
      "fields of every message",
      [{ a: 1 }, { b: "s" }],
      { type: "object", properties: { a: { type: "number" }, b: { type: "string" } } },
    ],
    [
      "a field of two types allows both",
      [{ a: 1 }, { a: null }],
      { type: "object", properties: { a: { type: ["null", "number"] } } },
    ],
    [
      "arrays with their items, empty ones without",
      [{ n: ["a"], e: [] }],
      { type: "object", properties: { n: { type: "array", items: { type: "string" } }, e: { type: "array" } } },
    ],
    [
      "an array's items of every message, an empty array adding none",
      [{ n: [] }, { n: [1, "a"] }],
      { type: "object", properties: { n: { type: "array", items: { type: ["number", "string"] } } } },
    ],
    [
      "a field named __proto__ as a field",
      [{ a: 1 }, JSON.parse('{"__proto__":"a"}')],
      { type: "object", properties: JSON.parse('{"a":{"type":"number"},"__proto__":{"type":"string"}}') },
    ],
    [
      "nested objects",
      [{ h: { stamp: { sec: 1 } } }],
      {
        type: "object",
        properties: {
          h: { type: "object", properties: { stamp: { type: "object", properties: { sec: { type: "number" } } } } },
        },
      },
    ],
  ])("%s", (_, messages, schema) => expect(schemaOf(messages)).toEqual(schema));
});

describe("plottable", () => {
  it.each([
    ["a JSON object in a String becomes the object", { data: '{"speed":0.5}' }, { speed: 0.5 }],
    ["a plain String stays", { data: "hello" }, { data: "hello" }],
    ["a JSON array stays text", { data: "[1]" }, { data: "[1]" }],
    ["a message with more fields stays", { data: "{}", other: 1 }, { data: "{}", other: 1 }],
    ["a number stays", 3, 3],
  ])("%s", (_, data, expected) => expect(plottable(data)).toEqual(expected));
});

describe("sampleSchemaName", () => {
  it.each([
    ["/joint_states", [{ name: ["a"], position: [1] }], "sensor_msgs/JointState"],
    ["/arm/joints", [{ name: ["a"], position: [], velocity: [] }], "sensor_msgs/JointState"],
    ["/battery", [{ percentage: 0.9 }], "hristudio.robot.battery"],
    ["/hristudio/robot_state", [{ posture: "stand" }], "hristudio.robot.hristudio.robot_state"],
    ["/names", [{ name: "a", position: 1 }], "hristudio.robot.names"],
  ])("%s", (topic, messages, name) => expect(sampleSchemaName(topic, schemaOf(messages))).toBe(name));
  it("names a topic for the ROS type the robot declared", () =>
    expect(sampleSchemaName("/battery", schemaOf([{ percentage: 1 }]), "sensor_msgs/msg/BatteryState")).toBe(
      "sensor_msgs/msg/BatteryState",
    ));
});

describe("nanosecondsAt", () => {
  // 2026-01-05T10:00:00.123Z: its nanoseconds pass 2^53, where float arithmetic was 64 ns off.
  const t0 = 1_767_607_200_123;
  it.each([
    [0, 1_767_607_200_123_000_000n],
    [20, 1_767_607_200_143_000_000n],
    [-5, 1_767_607_200_118_000_000n],
    [0.5, 1_767_607_200_123_500_000n],
  ])("%s ms after t0", (relMs, ns) => expect(nanosecondsAt(t0, relMs)).toBe(ns));
});

describe("logOf", () => {
  const event = (body: object) =>
    ({ seq: 1, relMs: 0, trialId: "t", serverTime: new Date(0), actorId: null, ...body }) as StoredEvent;
  it.each([
    ["an event as information", { type: "trial.started" }, 2, 'trial.started {"actorId":null}'],
    [
      "off script as a warning",
      { type: "step.entered", stepId: "s", via: "manual_jump", deviation: "manual_jump" },
      3,
      null,
    ],
    ["the robot's problem as a warning", { type: "robot.problem", text: "lost" }, 3, null],
    ["an emergency stop as an error", { type: "trial.emergency_stop" }, 4, null],
  ])("%s", (_, body, level, message) => {
    const log = logOf(event(body), 1_767_607_200_123_000_007n);
    expect(log).toMatchObject({ timestamp: { sec: 1_767_607_200, nsec: 123_000_007 }, level, name: "hristudio" });
    if (message) expect(log.message).toBe(message);
    expect(log.message.startsWith((body as { type: string }).type)).toBe(true);
  });

  it("stamps what the robot sensed with the robot's own time, keeping the message that matched", () => {
    const sensed = { type: "robot.sensed", event: "head_touched", at: 1_767_607_199_500, message: { data: true } };
    const log = logOf(event(sensed), 1_767_607_200_123_000_007n);
    expect(log).toMatchObject({ timestamp: { sec: 1_767_607_199, nsec: 500_000_000 }, level: 2 });
    expect(log.message).toBe(
      'robot.sensed {"actorId":null,"event":"head_touched","at":1767607199500,"message":{"data":true}}',
    );
  });
});
