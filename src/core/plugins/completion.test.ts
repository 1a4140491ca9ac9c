// Completion rules, as tables: which rule an action has, which done message
// is an action's, what an estimated duration comes to, and the robot's time.
import { describe, expect, it } from "vitest";
import { completionOf, estimatedMs, expectedDone, matchesDone, robotTimeOf, serviceRefusal } from "./completion";
import type { DoneMatch, PluginAction } from "./types";

const base = { id: "a", name: "A", category: "test", parameterSchema: { type: "object", properties: {} } } as const;
const publish = {
  ...base,
  ros2: { topic: "/speech", messageType: "std_msgs/msg/String", payloadMapping: { type: "static", payload: {} } },
} as PluginAction;

describe("the completion rule of an action", () => {
  it.each<[string, PluginAction, unknown]>([
    [
      "a declared rule wins",
      { ...publish, completion: { kind: "done_topic", topic: "/speech_done", messageType: "std_msgs/msg/String" } },
      { kind: "done_topic", topic: "/speech_done", messageType: "std_msgs/msg/String" },
    ],
    ["a topic publish without one is only delivered", publish, { kind: "delivered" }],
    [
      "a service call is done on its response",
      { ...base, ros2: { service: "/wake_up", serviceType: "std_srvs/srv/Trigger" } } as PluginAction,
      { kind: "service_response" },
    ],
    [
      "an HTTP request on its response",
      { ...base, http: { method: "POST", url: "say" } } as PluginAction,
      { kind: "http_response" },
    ],
    [
      "an SSH command on its exit",
      {
        ...base,
        ros2: { topic: "/x", messageType: "t", payloadMapping: { type: "ssh", sshCommand: "qicli call x" } },
      } as PluginAction,
      { kind: "command_exit" },
    ],
  ])("%s", (_, action, rule) => {
    expect(completionOf(action)).toEqual(rule);
  });
});

describe("matching a done message to its action", () => {
  const said: DoneMatch = { field: "data", equals: "said: {{text}}" };
  it.each<[string, DoneMatch | undefined, Record<string, unknown>, unknown, boolean]>([
    ["the same text", said, { text: "Hello" }, { data: "said: Hello" }, true],
    ["another text", said, { text: "Hello" }, { data: "said: Goodbye" }, false],
    ["text with braces and quotes, exactly", said, { text: `"{{x}}" \\ ok` }, { data: `said: "{{x}}" \\ ok` }, true],
    ["a prefix", { field: "data", startsWith: "done:" }, {}, { data: "done: wave" }, true],
    ["a prefix not there", { field: "data", startsWith: "done:" }, {}, { data: "started: wave" }, false],
    ["a nested field and a number", { field: "status.code", equals: 3 }, {}, { status: { code: 3 } }, true],
    ["a field missing", { field: "status.code", equals: 3 }, {}, { data: "x" }, false],
    ["no match rule: any message on the topic", undefined, {}, { data: "anything" }, true],
  ])("%s", (_, match, parameters, message, expected) => {
    const filled = expectedDone(match, parameters);
    if (!filled.ok) throw new Error(filled.reason);
    expect(matchesDone(filled.match, message)).toBe(expected);
  });

  it("a placeholder without a parameter is a plain reason", () => {
    expect(expectedDone(said, {})).toEqual({ ok: false, reason: expect.stringContaining('"text"') });
  });
});

describe("estimated durations and the robot's time", () => {
  it.each([
    [{ ms: 500 }, {}, 500],
    [{ msPerChar: 60, perCharOf: "text" }, { text: "Hello" }, 300],
    [{ ms: 100, msPerChar: 10, perCharOf: "text" }, { text: "赤い石" }, 130],
  ])("%j with %j lasts %i ms", (rule, parameters, ms) => {
    expect(estimatedMs(rule, parameters)).toBe(ms);
  });

  it.each([
    ["ROS 2 stamp", { header: { stamp: { sec: 1700000000, nanosec: 250_000_000 } } }, "2023-11-14T22:13:20.250Z"],
    ["ROS 1 stamp", { header: { stamp: { secs: 1700000000, nsecs: 0 } } }, "2023-11-14T22:13:20.000Z"],
    ["no header", { data: "said: hi" }, undefined],
    ["a zero stamp (unset)", { header: { stamp: { sec: 0, nanosec: 0 } } }, undefined],
  ])("%s", (_, message, time) => {
    expect(robotTimeOf(message)).toBe(time);
  });
});

describe("serviceRefusal: a reply that says the call was not done", () => {
  it.each<[string, unknown, string | null]>([
    ["success true", { success: true, message: "awake" }, null],
    ["no success field (std_srvs/Empty)", {}, null],
    ["no reply at all", null, null],
    [
      "success false, with the robot's words",
      { success: false, message: "motors hot" },
      "/wake_up answered that it did not succeed: motors hot",
    ],
    ["success false, no words", { success: false, message: "" }, "/wake_up answered that it did not succeed"],
  ])("%s", (_, reply, expected) => {
    expect(serviceRefusal("/wake_up", reply)).toBe(expected);
  });
});
