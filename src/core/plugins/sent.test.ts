import { describe, expect, it } from "vitest";
import type { Outgoing } from "./payload";
import { sentOverRos } from "./sent";

const read = () => ({});

describe("what rosbridge sends for an outgoing action", () => {
  it.each<[string, Outgoing, unknown]>([
    [
      "a topic message",
      { kind: "publish", topic: "/speech", messageType: "std_msgs/msg/String", message: { data: "Hi" } },
      { via: "topic", topic: "/speech", messageType: "std_msgs/msg/String", message: '{"data":"Hi"}' },
    ],
    [
      "a turn, with its stop",
      { kind: "motion", topic: "/cmd_vel", messageType: "T", message: { z: 1 }, stopAfterMs: 500, stop: { z: 0 } },
      { via: "topic", topic: "/cmd_vel", messageType: "T", message: '{"z":1}', stopAfterMs: 500, stop: '{"z":0}' },
    ],
    [
      "a service call",
      { kind: "call", service: "/wake", serviceType: "std_srvs/srv/Trigger", args: {} },
      { via: "service", service: "/wake", serviceType: "std_srvs/srv/Trigger", args: "{}" },
    ],
    [
      "an action goal",
      { kind: "goal", action: "/navigate", actionType: "A", goal: { x: 1 } },
      { via: "action", action: "/navigate", actionType: "A", goal: '{"x":1}' },
    ],
    ["a topic read sends nothing", { kind: "read", topic: "/odom", messageType: "T", read }, null],
    ["an SSH command is not rosbridge's", { kind: "ssh", command: "qicli call" }, null],
    ["nothing to send", { kind: "none", reason: "no dispatch block" }, null],
  ])("%s", (_, outgoing, sent) => expect(sentOverRos(outgoing)).toEqual(sent));
});
