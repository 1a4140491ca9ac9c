// HRIStudio's TurtleBot3 Waffle file, unmodified, through the real roslib
// client into the simulated robot over a real socket: its ROS 2 action goal
// (navigate_to_pose: goal, feedback, result, cancel), its named transforms
// (a velocity, a turn then a stop, a reading of the odometry), and the
// actions it needs but this platform does not have, refused with the reason.
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin, type PluginAction } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";

const waffle = (() => {
  const file = "turtlebot3-waffle.json";
  const loaded = loadPlugin(file, readFileSync(`tests/fixtures/hristudio-plugins/plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(loaded.errors.map((e) => e.reason).join("; "));
  return loaded.value as Plugin;
})();
const action = (id: string) => waffle.actions.find((a) => a.id === id)!;

let sim: Simulator | null = null;
let transport: RosbridgeTransport | null = null;
afterEach(async () => {
  await transport?.close();
  await sim?.close();
  transport = sim = null;
});

async function setUp() {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(waffle) });
  transport = new RosbridgeTransport({ url: sim.url, plugin: waffle });
  await transport.connect();
  return { sim, transport };
}

const sent = (sim: Simulator, op: string) => sim.received.filter((r) => r.message.op === op).map((r) => r.message);
const round = (value: unknown) =>
  JSON.parse(JSON.stringify(value), (_, v) => (typeof v === "number" ? Math.round(v * 1e6) / 1e6 : v));

describe("a ROS 2 action goal: navigate_to_pose", () => {
  it("sends Nav2's goal with the exact pose, hears feedback, and completes on the robot's result", async () => {
    const { sim, transport } = await setUp();
    const outcome = await transport.dispatch(action("move_to_pose"), { x: 0.3, y: -0.4, theta: Math.PI / 2 });
    expect(outcome).toMatchObject({
      status: "completed",
      detail: {
        action: "/navigate_to_pose",
        result: { error_code: 0, error_msg: "" },
        confirmation: { by: "action_result", confirmed: true, source: "/navigate_to_pose" },
      },
    });
    expect((outcome as unknown as { detail: { feedback: number } }).detail.feedback).toBeGreaterThan(0);
    const [goal] = sent(sim, "send_action_goal");
    expect(round({ ...goal, id: undefined })).toEqual(
      round({
        op: "send_action_goal",
        action: "/navigate_to_pose",
        action_type: "nav2_msgs/action/NavigateToPose",
        args: {
          pose: {
            header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "map" },
            pose: {
              position: { x: 0.3, y: -0.4, z: 0 },
              orientation: { x: 0, y: 0, z: Math.SQRT1_2, w: Math.SQRT1_2 },
            },
          },
          behavior_tree: "",
        },
        feedback: true,
      }),
    );
    expect(round(sim.state.pose)).toEqual(round({ x: 0.3, y: -0.4, theta: Math.PI / 2 }));
  });

  it("cancels a goal still running at the action's deadline, and the robot stops there", async () => {
    const { sim, transport } = await setUp();
    const short: PluginAction = { ...action("move_to_pose"), timeout: 300 };
    const outcome = await transport.dispatch(short, { x: 50, y: 0, theta: 0 });
    expect(outcome.status).toBe("timed_out");
    const [goal] = sent(sim, "send_action_goal");
    await expect
      .poll(() => sent(sim, "cancel_action_goal"))
      .toEqual([{ op: "cancel_action_goal", id: goal!.id, action: "/navigate_to_pose" }]);
    const stoppedAt = sim.state.pose.x;
    expect(stoppedAt).toBeGreaterThan(0);
    expect(stoppedAt).toBeLessThan(50);
    await new Promise((r) => setTimeout(r, 200));
    expect(sim.state.pose.x).toBe(stoppedAt);
  });

  it("fails with the robot's reason when it has no such action server", async () => {
    const { transport } = await setUp();
    const dock: PluginAction = {
      ...action("move_to_pose"),
      id: "dock",
      ros2: { ...(action("move_to_pose").ros2 as object), action: "/dock" } as PluginAction["ros2"],
    };
    expect(await transport.dispatch(dock, { x: 0, y: 0, theta: 0 })).toEqual({
      status: "failed",
      reason: "the ROS 2 action /dock did not succeed: Action was aborted: Action /dock does not exist",
    });
  });
});

describe("every action of HRIStudio's Burger file reaches the simulator with its exact payload", () => {
  const burger = (() => {
    const file = "turtlebot3-burger.json";
    const loaded = loadPlugin(file, readFileSync(`tests/fixtures/hristudio-plugins/plugins/${file}`, "utf8"));
    if (!loaded.ok) throw new Error("fixture");
    return loaded.value as Plugin;
  })();
  const zero = { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } };
  it.each([
    [
      "move_velocity",
      { linear: -0.22, angular: 2.84 },
      "publish",
      { linear: { x: -0.22, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 2.84 } },
    ],
    ["stop_robot", {}, "publish", zero],
    [
      "move_to_pose",
      { x: 0.2, y: 0.1, theta: 0 },
      "send_action_goal",
      {
        pose: {
          header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "map" },
          pose: { position: { x: 0.2, y: 0.1, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
        },
        behavior_tree: "",
      },
    ],
  ])("%s", async (id, parameters, op, payload) => {
    sim = await startSimulator({ port: 0, nodes: simulatedRobot(burger) });
    transport = new RosbridgeTransport({ url: sim.url, plugin: burger });
    await transport.connect();
    const outcome = await transport.dispatch(burger.actions.find((a) => a.id === id)!, parameters);
    expect(outcome.status).toBe("completed");
    const s = sim;
    await expect.poll(() => sent(s, op).map((m) => (op === "publish" ? m.msg : m.args))).toEqual([payload]);
  });
});

describe("named transforms reach the robot as HRIStudio's file means them", () => {
  it("transformToTwist: the exact velocity on /cmd_vel", async () => {
    const { sim, transport } = await setUp();
    expect(await transport.dispatch(action("move_velocity"), { linear: 0.2, angular: -1 })).toMatchObject({
      status: "completed",
    });
    await expect
      .poll(() =>
        sent(sim, "publish")
          .filter((m) => m.topic === "/cmd_vel")
          .map((m) => m.msg),
      )
      .toEqual([{ linear: { x: 0.2, y: 0, z: 0 }, angular: { x: 0, y: 0, z: -1 } }]);
  });

  it("emergency_stop: the exact zero velocity on /cmd_vel", async () => {
    const { sim, transport } = await setUp();
    expect(await transport.dispatch(action("emergency_stop"), {})).toMatchObject({ status: "completed" });
    await expect
      .poll(() =>
        sent(sim, "publish")
          .filter((m) => m.topic === "/cmd_vel")
          .map((m) => m.msg),
      )
      .toEqual([{ linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }]);
  });

  it("transformToRotation: a turn at the fraction of the Waffle's 1.82 rad/s, then a stop once the angle is covered", async () => {
    const { sim, transport } = await setUp();
    const outcome = await transport.dispatch(action("rotate_in_place"), { angle: -0.91, speed: 1 });
    expect(outcome).toEqual({
      status: "completed",
      detail: { topic: "/cmd_vel", turnedForMs: 500, confirmation: { by: "delivered", confirmed: false } },
    });
    await expect
      .poll(() =>
        sent(sim, "publish")
          .filter((m) => m.topic === "/cmd_vel")
          .map((m) => m.msg),
      )
      .toEqual([
        { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: -1.82 } },
        { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } },
      ]);
    expect(sim.state.velocity).toEqual({ linear: 0, angular: 0 });
  });

  it("extractRobotState: reads the robot's odometry and completes with where it is", async () => {
    const { sim, transport } = await setUp();
    Object.assign(sim.state.pose, { x: 1.25, y: -0.5, theta: Math.PI / 2 });
    const outcome = await transport.dispatch(action("get_robot_state"), {});
    expect(outcome.status).toBe("completed");
    const { topic, state } = (outcome as unknown as { detail: { topic: string; state: Record<string, unknown> } })
      .detail;
    expect(topic).toBe("/odom");
    expect(round({ ...state, stamp: undefined })).toEqual(
      round({ frame: "odom", x: 1.25, y: -0.5, theta: Math.PI / 2, linear: 0, angular: 0 }),
    );
    expect(sent(sim, "publish")).toEqual([]);
  });

  it.each([
    ["capture_image", { filename: "a.jpg" }, /saves a picture from the robot's camera/],
    ["scan_environment", { duration: 2 }, /records laser scans/],
    ["follow_wall", { side: "left", distance: 0.3, duration: 10 }, /follows a wall/],
  ])("%s: not sent, failed with the reason", async (id, parameters, reason) => {
    const { sim, transport } = await setUp();
    const outcome = await transport.dispatch(action(id), parameters);
    expect(outcome).toEqual({ status: "failed", reason: expect.stringMatching(reason) });
    expect(sim.received.filter((r) => r.message.op !== "call_service")).toEqual([]);
  });
});
