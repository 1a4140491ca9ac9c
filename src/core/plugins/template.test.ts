import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { fillTemplate, outgoingFor, placeholders, type JsonValue, type PluginAction } from "./index";

const hostile = JSON.parse(
  readFileSync("tests/fixtures/rosbridge-transcripts/02-hostile-text-roundtrip.jsonl", "utf8").split("\n")[4]!,
).frame.msg.data as string;

describe("fillTemplate", () => {
  const cases: Array<[string, JsonValue, Record<string, unknown>, JsonValue]> = [
    ["whole string becomes the JSON value (number)", { x: "{{speed}}" }, { speed: 0.3 }, { x: 0.3 }],
    ["whole string becomes the JSON value (object)", { x: "{{pose}}" }, { pose: { a: [1, 2] } }, { x: { a: [1, 2] } }],
    ["whole string becomes the JSON value (boolean)", ["{{on}}"], { on: false }, [false]],
    ["spaces inside the braces", { x: "{{ text }}" }, { text: "hi" }, { x: "hi" }],
    ["inside a longer string, as text", { data: "say {{text}}!" }, { text: 'a "b" {c}' }, { data: 'say a "b" {c}!' }],
    ["a number inside a longer string", { data: "v={{n}}" }, { n: 2 }, { data: "v=2" }],
    [
      "a value containing a placeholder is not expanded again",
      { data: "{{text}}" },
      { text: "{{text}} {{other}}" },
      { data: "{{text}} {{other}}" },
    ],
    ["no placeholders: unchanged", { linear: { x: 0.1 } }, {}, { linear: { x: 0.1 } }],
    ["keys are never templates", { "{{text}}": 1 }, { text: "k" }, { "{{text}}": 1 }],
    [
      "quotes, backslashes, newlines, NUL",
      { data: "{{text}}" },
      { text: "\"'`\\ \n\r\t\u0000 \\n" },
      { data: "\"'`\\ \n\r\t\u0000 \\n" },
    ],
  ];
  it.each(cases)("%s", (_, template, parameters, expected) => {
    expect(fillTemplate(template, parameters)).toEqual({ ok: true, value: expected });
  });

  it("carries the hostile text of transcript 02 unchanged", () => {
    const filled = fillTemplate({ data: "{{text}}" }, { text: hostile });
    expect(filled.ok && (filled.value as { data: string }).data).toBe(hostile);
    expect(hostile.length).toBe(8771);
  });

  it("names a missing parameter and where it was needed", () => {
    expect(fillTemplate({ linear: { x: "{{speed}}" } }, {})).toEqual({
      ok: false,
      path: "/linear/x",
      reason: 'no value for parameter "speed"',
    });
  });

  it("keeps a __proto__ key as data", () => {
    const filled = fillTemplate(JSON.parse('{"__proto__": {"polluted": "{{x}}"}}'), { x: 1 });
    expect(filled.ok && Object.keys(filled.value as object)).toEqual(["__proto__"]);
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });

  it("lists placeholders with their JSON Pointers", () => {
    expect(placeholders({ a: ["x {{one}}", { "b/c": "{{two}}" }] })).toEqual([
      { path: "/a/0", name: "one" },
      { path: "/a/1/b~1c", name: "two" },
    ]);
  });
});

describe("outgoingFor", () => {
  const say: PluginAction = {
    id: "say_with_emotion",
    name: "Say",
    category: "speech",
    parameterSchema: { type: "object", properties: { text: { type: "string" }, emotion: { type: "string" } } },
    ros2: {
      topic: "/speech",
      messageType: "std_msgs/msg/String",
      payloadMapping: { type: "transform", transformFn: "transformToEmotionSpeech" },
    },
  };
  it.each([
    ["happy", { text: "Hi", emotion: "happy" }, "\\rspd=110\\\\vct=115\\Hi"],
    ["sad", { text: "Hi", emotion: "sad" }, "\\rspd=85\\\\vct=90\\Hi"],
    ["neutral is the text alone", { text: "Hi", emotion: "neutral" }, "Hi"],
    ["no emotion is the text alone", { text: hostile }, hostile],
  ])("transformToEmotionSpeech: %s", (_, parameters, data) => {
    expect(outgoingFor(say, parameters)).toEqual({
      kind: "publish",
      topic: "/speech",
      messageType: "std_msgs/msg/String",
      message: { data },
    });
  });

  it("fills service arguments as JSON values", () => {
    const led: PluginAction = {
      id: "led",
      name: "LED",
      category: "display",
      parameterSchema: { type: "object", properties: { on: { type: "boolean" } } },
      ros2: { service: "/set_led", serviceType: "std_srvs/srv/SetBool", args: { data: "{{on}}" } },
    };
    expect(outgoingFor(led, { on: true })).toEqual({
      kind: "call",
      service: "/set_led",
      serviceType: "std_srvs/srv/SetBool",
      args: { data: true },
    });
  });
});
