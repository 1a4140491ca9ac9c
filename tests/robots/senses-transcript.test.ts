// The NAO6 plugin's events against rosbridge frames of the real message
// types (tests/fixtures/robot-senses, written by hand in the recorded
// frames' form): each frame as it came on the wire, matched against every
// event on its topic, in order, at the robot's stamp when it has one.
import { readFileSync } from "node:fs";
import { expect, it } from "vitest";
import { loadPlugin, messageTime, type Plugin, type SenseState, sense, UNSENSED } from "../../src/core/plugins";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
/** The runtime's clock when the recording began: a frame without a stamp is taken at this plus its t_ms. */
const STARTED = Date.UTC(2026, 10, 27, 9, 0, 0);
const ROBOT_SEC = 1795349400;

type Line = { dir: string; t_ms: number; frame?: { op?: string; topic?: string; msg?: unknown }; raw?: string };
const lines = readFileSync("tests/fixtures/robot-senses/nao6-senses.jsonl", "utf8")
  .split("\n")
  .filter(Boolean)
  .map((line) => JSON.parse(line) as Line);

it("the NAO6's touches, heard words and sonar make its events, once each", () => {
  const states = new Map<string, SenseState>();
  const sensed: Array<[string, number]> = [];
  for (const line of lines) {
    if (line.dir !== "recv") continue;
    // The text on the wire, as a client reads it.
    const frame = (line.raw ? JSON.parse(line.raw) : line.frame) as NonNullable<Line["frame"]>;
    if (frame.op !== "publish") continue;
    for (const event of nao.events!.filter((e) => e.topic === frame.topic)) {
      const step = sense(
        event,
        states.get(event.id) ?? UNSENSED,
        frame.msg,
        messageTime(frame.msg, STARTED + line.t_ms),
      );
      states.set(event.id, step.state);
      if (step.sensed) sensed.push([step.sensed.event, step.sensed.at]);
    }
  }
  expect(sensed).toEqual([
    // Pressed in the middle: the head; released: nothing.
    ["head_touched", STARTED + 400],
    // Pressed at the front: the front, not the middle.
    ["head_front_touched", STARTED + 1650],
    ["left_hand_touched", STARTED + 2650],
    ["right_foot_bumped", STARTED + 3500],
    // "ready" at 0.42 is not heard; at 0.71 it is; "yes" at 0.55 beside "ready" at 0.3 is only a yes.
    ["heard_ready", STARTED + 7000],
    ["heard_yes", STARTED + 9100],
    // Close for a second by the robot's clock, flapping around 0.5 m: one; gone and back: one more.
    ["someone_close_left", ROBOT_SEC * 1000 + 1300],
    ["someone_close_left", ROBOT_SEC * 1000 + 3000],
  ]);
});
