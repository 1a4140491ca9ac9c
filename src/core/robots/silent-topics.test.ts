import { describe, expect, it } from "vitest";
import { refusalOf, refusedAdvertise, silence, type WatchedTopic } from "./silent-topics";

const joints: WatchedTopic = {
  topic: "/joint_states",
  messageType: "sensor_msgs/msg/JointState",
  kind: "state",
  throttleRate: 100,
  since: 0,
  lastAt: null,
  refused: null,
  waitedOut: false,
};
const battery: WatchedTopic = {
  ...joints,
  topic: "/battery",
  messageType: "sensor_msgs/msg/BatteryState",
  throttleRate: undefined,
};
const touch: WatchedTopic = {
  ...joints,
  topic: "/head_touch",
  messageType: "naoqi_bridge_msgs/msg/HeadTouch",
  kind: "event",
  throttleRate: undefined,
};
const done: WatchedTopic = { ...joints, topic: "/speech_done", messageType: "std_msgs/msg/String", kind: "completion" };

describe("which declared topics are silent, and why", () => {
  it.each<[string, WatchedTopic, number, string | null]>([
    ["a state topic heard lately", { ...joints, lastAt: 9_000 }, 10_000, null],
    ["a state topic not yet heard, inside its window", joints, 4_999, null],
    [
      "a ROS 2 type name never heard: the ROS 1 bridge is the usual cause",
      joints,
      5_000,
      "The robot never sent /joint_states (expected about every 0.1 s; nothing in 5 s): the usual causes are a ROS 1 bridge, which refuses the ROS 2 type name sensor_msgs/msg/JointState without telling us (it names it sensor_msgs/JointState), or nothing on the robot publishing /joint_states.",
    ],
    [
      "a ROS 1 type name never heard: nothing publishes it",
      { ...battery, messageType: "sensor_msgs/BatteryState" },
      6_000,
      "The robot never sent /battery (expected about every 1 s; nothing in 5 s): the usual cause is that nothing on the robot publishes /battery, or publishes it as another type than sensor_msgs/BatteryState.",
    ],
    ["a slow topic gets five of its intervals", { ...battery, throttleRate: 2000 }, 9_999, null],
    [
      "a topic that spoke, then stopped",
      { ...joints, lastAt: 1_000 },
      6_000,
      "The robot stopped sending /joint_states (expected about every 0.1 s; nothing for 5 s): the node that publishes it on the robot may have stopped.",
    ],
    [
      "a subscription the bridge refused for its ROS 2 type name, at once",
      { ...joints, refused: "sensor_msgs/msg/JointState is not a valid type string" },
      1,
      "The robot never sent /joint_states (expected about every 0.1 s): the bridge refused its type sensor_msgs/msg/JointState — a ROS 1 bridge names it sensor_msgs/JointState.",
    ],
    [
      "a subscription refused for a type the graph already has",
      {
        ...joints,
        messageType: "std_msgs/String",
        refused:
          "Tried to register topic /joint_states with type std_msgs/String but it is already established with type sensor_msgs/JointState",
      },
      1,
      "The robot never sent /joint_states (expected about every 0.1 s): the bridge refused to subscribe to it as std_msgs/String: Tried to register topic /joint_states with type std_msgs/String but it is already established with type sensor_msgs/JointState.",
    ],
    ["a completion topic no action has waited on", done, 60_000, null],
    ["an event topic never heard: nothing was sensed yet, no fault", touch, 60_000, null],
    ["an event topic that spoke, then fell quiet", { ...touch, lastAt: 1_000 }, 60_000, null],
    [
      "an event topic the bridge refused",
      { ...touch, refused: "naoqi_bridge_msgs/msg/HeadTouch is not a valid type string" },
      1,
      "The robot never sent /head_touch (expected when the robot senses something): the bridge refused its type naoqi_bridge_msgs/msg/HeadTouch — a ROS 1 bridge names it naoqi_bridge_msgs/HeadTouch.",
    ],
    [
      "a completion topic an action waited on to its timeout, never heard",
      { ...done, waitedOut: true },
      60_000,
      "The robot never sent /speech_done (expected after each action that waits for it; an action waited for it until its timeout): the usual causes are a ROS 1 bridge, which refuses the ROS 2 type name std_msgs/msg/String without telling us (it names it std_msgs/String), or nothing on the robot publishing /speech_done.",
    ],
    [
      "a completion topic that has answered before: a timeout is the action's own",
      { ...done, waitedOut: true, lastAt: 5 },
      60_000,
      null,
    ],
    [
      "a completion topic the bridge refused",
      { ...done, refused: "std_msgs/msg/String is not a valid type string" },
      1,
      "The robot never sent /speech_done (expected after each action that waits for it): the bridge refused its type std_msgs/msg/String — a ROS 1 bridge names it std_msgs/String.",
    ],
  ])("%s", (_, topic, now, said) => {
    expect(silence(topic, now)).toBe(said);
  });

  it("says the same words at every later check, so the wizard is told once", () => {
    expect(silence(joints, 5_000)).toBe(silence(joints, 50_000));
  });
});

describe("what a bridge's status frame refused", () => {
  it.each<[string, unknown, ReturnType<typeof refusalOf>]>([
    [
      "a refused subscription, in the recorded log line's words (06, sub-js-ros2-name)",
      {
        op: "status",
        level: "error",
        id: "subscribe:/joint_states:3",
        msg: "subscribe: sensor_msgs/msg/JointState is not a valid type string",
      },
      { op: "subscribe", topic: "/joint_states", text: "sensor_msgs/msg/JointState is not a valid type string" },
    ],
    [
      "a refused advertise",
      {
        op: "status",
        level: "error",
        id: "advertise:/speech:1",
        msg: "advertise: std_msgs/msg/String is not a valid type string.",
      },
      { op: "advertise", topic: "/speech", text: "std_msgs/msg/String is not a valid type string" },
    ],
    ["a warning is not a refusal", { op: "status", level: "warning", id: "subscribe:/a:1", msg: "slow" }, null],
    ["an error naming no subscription", { op: "status", level: "error", msg: "motor hot" }, null],
    ["an id of another op", { op: "status", level: "error", id: "call_service:/wake_up:2", msg: "x" }, null],
    ["a publish frame", { op: "publish", topic: "/a", msg: {} }, null],
    ["not an object", "status", null],
  ])("%s", (_, frame, refusal) => {
    expect(refusalOf(frame)).toEqual(refusal);
  });
});

describe("an action's topic the bridge would not carry", () => {
  it.each<[string, string, string, string]>([
    [
      "std_msgs/msg/String",
      "std_msgs/msg/String is not a valid type string",
      "ROS 2 spelling",
      "The robot's bridge refused to carry /speech: it refused the type std_msgs/msg/String — a ROS 1 bridge names it std_msgs/String.",
    ],
    [
      "std_msgs/Int32",
      "Tried to register topic /speech with type std_msgs/Int32 but it is already established with type std_msgs/String",
      "a type the graph already has",
      "The robot's bridge refused to carry /speech as std_msgs/Int32: Tried to register topic /speech with type std_msgs/Int32 but it is already established with type std_msgs/String.",
    ],
    ["", "x", "no type known", "The robot's bridge refused to carry /speech: x."],
  ])("%s (%s)", (type, text, _, said) => {
    expect(refusedAdvertise("/speech", type || null, text)).toBe(said);
  });
});
