// HRIStudio's named transforms, each a pure function checked case by case.
// transformToTwist and transformToPoseStamped match HRIStudio's own (its
// plugin store) but for the stamp; the other two HRIStudio names but never wrote.
import { describe, expect, it } from "vitest";
import { actionGoal } from "./goal";
import { maxTurnOf, transformOf, type Transform } from "./transforms";

const build = (name: string, parameters: Record<string, unknown>) =>
  (transformOf(name) as Extract<Transform, { kind: "message" }>).build(parameters);
const half = Math.SQRT1_2;
const close = (value: unknown) =>
  JSON.parse(JSON.stringify(value), (_, v) => (typeof v === "number" ? Math.round(v * 1e9) / 1e9 : v));

describe("transformToTwist", () => {
  it.each([
    [
      { linear: 0.2, angular: -1.5 },
      { linear: { x: 0.2, y: 0, z: 0 }, angular: { x: 0, y: 0, z: -1.5 } },
    ],
    [{ linear: 0.1 }, { linear: { x: 0.1, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }],
    [{}, { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }],
  ])("%j", (parameters, message) => expect(build("transformToTwist", parameters)).toEqual(message));
});

describe("transformToPoseStamped", () => {
  it.each([
    [{ x: 1, y: 2, theta: 0 }, [1, 2], { x: 0, y: 0, z: 0, w: 1 }],
    [{ x: -0.5, y: 0, theta: Math.PI / 2 }, [-0.5, 0], { x: 0, y: 0, z: half, w: half }],
    [{ x: 0, y: 0, theta: Math.PI }, [0, 0], { x: 0, y: 0, z: 1, w: 0 }],
    [{ x: 3, y: 4, theta: -Math.PI / 2 }, [3, 4], { x: 0, y: 0, z: -half, w: half }],
  ])("%j", (parameters, [x, y], orientation) => {
    expect(close(build("transformToPoseStamped", parameters))).toEqual(
      close({
        header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "map" },
        pose: { position: { x, y, z: 0 }, orientation },
      }),
    );
  });

  it("is Nav2's NavigateToPose goal when sent to an action, as HRIStudio's TurtleBot files mean it", () => {
    const pose = build("transformToPoseStamped", { x: 1, y: 0, theta: 0 });
    expect(actionGoal({ action: "/navigate_to_pose", messageType: "geometry_msgs/msg/PoseStamped" }, pose)).toEqual({
      ok: true,
      actionType: "nav2_msgs/action/NavigateToPose",
      goal: { pose, behavior_tree: "" },
    });
  });
});

describe("transformToRotation", () => {
  const rotation = transformOf("transformToRotation") as Extract<Transform, { kind: "motion" }>;
  const stop = { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } };
  it.each([
    ["a quarter turn left at half of 1.82 rad/s", { angle: Math.PI / 2, speed: 0.5 }, 0.91, 1726],
    ["a half turn right at full speed", { angle: -Math.PI, speed: 1 }, -1.82, 1726],
    ["the schema's default speed (half)", { angle: 1.82 }, 0.91, 2000],
    ["no angle: no turn", { angle: 0, speed: 1 }, 0, 0],
  ])("%s", (_, parameters, turn, stopAfterMs) => {
    expect(close(rotation.build(parameters, 1.82))).toEqual({
      message: { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: turn } },
      stopAfterMs,
      stop,
    });
  });
});

describe("extractRobotState", () => {
  const read = (transformOf("extractRobotState") as Extract<Transform, { kind: "reading" }>).read;
  const odometry = (z: number, w: number) => ({
    header: { stamp: { sec: 12, nanosec: 5 }, frame_id: "odom" },
    child_frame_id: "base_footprint",
    pose: { pose: { position: { x: 1.5, y: -2, z: 0 }, orientation: { x: 0, y: 0, z, w } }, covariance: [] },
    twist: { twist: { linear: { x: 0.1, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0.3 } }, covariance: [] },
  });
  it.each([
    ["facing along x", odometry(0, 1), 0],
    ["turned a quarter left", odometry(half, half), Math.PI / 2],
    ["turned a quarter right", odometry(-half, half), -Math.PI / 2],
  ])("%s", (_, message, theta) => {
    expect(close(read(message))).toEqual(
      close({ frame: "odom", stamp: { sec: 12, nanosec: 5 }, x: 1.5, y: -2, theta, linear: 0.1, angular: 0.3 }),
    );
  });
  it("reads what a message that is not odometry gives as zeros, never throws", () => {
    expect(read("nonsense")).toEqual({
      frame: "",
      stamp: { sec: 0, nanosec: 0 },
      x: 0,
      y: 0,
      theta: 0,
      linear: 0,
      angular: 0,
    });
  });
});

describe("the robot's top turning speed", () => {
  const twistAction = (maximum?: number) => ({
    id: "move",
    name: "Move",
    category: "movement",
    parameterSchema: {
      type: "object" as const,
      properties: { angular: { type: "number", ...(maximum ? { maximum } : {}) } },
    },
    ros2: {
      topic: "/cmd_vel",
      messageType: "geometry_msgs/msg/Twist",
      payloadMapping: { type: "transform" as const, transformFn: "transformToTwist" },
    },
  });
  it.each([
    [[twistAction(1.82)], 1.82],
    [[twistAction()], null],
    [[], null],
  ])("%#", (actions, expected) => expect(maxTurnOf({ actions })).toBe(expected));
});
