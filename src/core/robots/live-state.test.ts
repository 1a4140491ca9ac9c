import { describe, expect, it } from "vitest";
import { batteryLow, carriedPosture, foldLiveState, UNKNOWN_STATE, type LiveRobotState } from "./live-state";
import { initialState, ROBOT_STATE_TOPIC } from "./robot-state";

const report = (changes: object) => ({ data: JSON.stringify({ ...initialState(), ...changes }) });
const batteryState = (percentage: number) => ({ percentage, power_supply_status: 2, voltage: 25 });

describe("the robot's live state, as the wizard sees it", () => {
  it.each<[string, LiveRobotState, string, unknown, LiveRobotState]>([
    [
      "the simulated robot speaking, with its text",
      UNKNOWN_STATE,
      ROBOT_STATE_TOPIC,
      report({ speaking: "Hello there", posture: "sit", battery: 87.456 }),
      { speaking: "Hello there", gesture: null, posture: "sit", battery: 87.5 },
    ],
    [
      "an animation shown as the gesture",
      UNKNOWN_STATE,
      ROBOT_STATE_TOPIC,
      report({ animation: "wave" }),
      { speaking: null, gesture: "wave", posture: "stand", battery: 100 },
    ],
    [
      "a real robot's BatteryState: percentage 0–1 as percent",
      UNKNOWN_STATE,
      "/battery",
      batteryState(0.153),
      { ...UNKNOWN_STATE, battery: 15.3 },
    ],
    ["a battery that does not know its charge", UNKNOWN_STATE, "/battery", batteryState(Number.NaN), UNKNOWN_STATE],
    [
      "joint states change nothing",
      UNKNOWN_STATE,
      "/joint_states",
      { name: ["HeadYaw"], position: [0] },
      UNKNOWN_STATE,
    ],
    ["a report that is not JSON", UNKNOWN_STATE, ROBOT_STATE_TOPIC, { data: "{oops" }, UNKNOWN_STATE],
  ])("%s", (_, before, topic, message, after) => {
    expect(foldLiveState(before, topic, message)).toEqual(after);
  });

  it("returns the same state when nothing the wizard sees changed (nothing to send)", () => {
    const state = foldLiveState(UNKNOWN_STATE, "/battery", batteryState(0.5));
    expect(foldLiveState(state, "/battery", batteryState(0.5))).toBe(state);
  });

  it.each([
    [null, false],
    [19.9, true],
    [20, false],
  ])("battery %s low: %s", (battery, low) => {
    expect(batteryLow({ ...UNKNOWN_STATE, battery })).toBe(low);
  });
});

describe("a posture carried into the next trial", () => {
  it.each<[string, string | undefined, LiveRobotState | null, string | null]>([
    [
      "sitting, as the last trial left it",
      "NAO",
      { ...UNKNOWN_STATE, posture: "sit" },
      'NAO is in the posture "sit", as the last trial or session left it; it starts in "stand". Set its posture before the participant arrives if the protocol expects "stand".',
    ],
    ["standing, as it starts: nothing to say", "NAO", { ...UNKNOWN_STATE, posture: "stand" }, null],
    ["a robot that reports no posture", "NAO", UNKNOWN_STATE, null],
    ["no state yet", "NAO", null, null],
  ])("%s", (_, name, state, notice) => {
    expect(carriedPosture(name, state)).toBe(notice);
  });
});
