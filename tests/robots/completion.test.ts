// Completion confirmed by the robot: the first-party NAO6 plugin's rules
// against the simulated robot over a real socket. A say is completed when the
// robot has finished speaking, an animation when it has run, each with what
// confirmed it; a lost link fails what was waiting. And an emergency stop's
// halt silences speech and animation, not only the wheels.
import { readFileSync } from "node:fs";
import { afterEach, describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../../src/core/plugins";
import { simulatedRobot, startSimulator, type Simulator } from "../../src/robots/simulator";
import { RosbridgeTransport } from "../../src/robots/transports/rosbridge";
import { pluginRobot } from "../../src/runtime/robot-link";

const nao = (loadPlugin("nao6-ros2.json", readFileSync("plugins/nao6-ros2.json", "utf8")) as { value: Plugin }).value;
const action = (id: string) => nao.actions.find((a) => a.id === id)!;

let sim: Simulator | null = null;
let transport: RosbridgeTransport | null = null;
afterEach(async () => {
  await transport?.close();
  await sim?.close();
  transport = sim = null;
});

async function setUp(msPerChar = 20, animationMs = 300) {
  sim = await startSimulator({ port: 0, nodes: simulatedRobot(nao, { msPerChar, animationMs }) });
  transport = new RosbridgeTransport({ url: sim.url, backoffMs: { first: 50, max: 200 } });
  await transport.connect();
  return { sim, transport };
}

describe("completion confirmed by the robot", () => {
  it("a say is completed once the robot has finished speaking it, confirmed by its done topic", async () => {
    const { sim, transport } = await setUp();
    const text = `She said "{{text}}" \\ 赤い石`;
    const outcome = transport.dispatch(action("say_text"), { text });
    await expect.poll(() => sim.state.speaking).toBe(text);
    expect(await outcome).toEqual({
      status: "completed",
      detail: { topic: "/speech", confirmation: { by: "done_topic", confirmed: true, source: "/speech_done" } },
    });
    expect(sim.state).toMatchObject({ speaking: null, lastSaid: text });
  });

  it("a say longer than the action's timeout is given its speaking time (the rule's msPerChar), not timed out", async () => {
    const { sim, transport } = await setUp(20);
    const text = "x".repeat(60); // 1.2 s of speech at 20 ms a character; the rule allows 100 ms a character more
    const outcome = await transport.dispatch({ ...action("say_text"), timeout: 500 }, { text });
    expect(outcome).toMatchObject({ status: "completed", detail: { confirmation: { by: "done_topic" } } });
    expect(sim.state.lastSaid).toBe(text);
  });

  it("two says at once are each completed by their own done message", async () => {
    const { transport } = await setUp();
    let longDone = false;
    const long = transport.dispatch(action("say_text"), { text: "a much longer sentence to say" });
    void long.then(() => (longDone = true));
    const short = transport.dispatch(action("say_text"), { text: "hi" });
    expect((await short).status).toBe("completed");
    // The short one's "said: hi" did not complete the long one, still being spoken.
    expect(longDone).toBe(false);
    expect((await long).status).toBe("completed");
  });

  it("an animation is completed once it has run", async () => {
    const { sim, transport } = await setUp();
    const outcome = transport.dispatch(action("play_animation_hey"), {});
    await expect.poll(() => sim.state.animation).toBe("animations/Stand/Gestures/Hey_1");
    expect(await outcome).toMatchObject({
      status: "completed",
      detail: { confirmation: { by: "done_topic", confirmed: true, source: "/animation_done" } },
    });
    expect(sim.state.animation).toBeNull();
  });

  it("a say whose robot is lost before it says it is done is sent, outcome unknown, with why; never completed", async () => {
    const { sim, transport } = await setUp(200);
    const outcome = transport.dispatch(action("say_text"), { text: "cut off by the network" });
    await expect.poll(() => sim.state.speaking).toBe("cut off by the network");
    sim.faults.refuseConnections(true);
    sim.faults.dropConnections();
    expect(await outcome).toEqual({
      status: "unknown",
      reason: expect.stringContaining("the link was lost before the robot said it was done"),
    });
  });

  it("a plugin's rule that names a parameter the action lacks fails plainly, sending nothing", async () => {
    const { sim, transport } = await setUp();
    const bad = {
      ...action("stop_walking"),
      completion: {
        kind: "done_topic" as const,
        topic: "/speech_done",
        messageType: "std_msgs/msg/String",
        match: { field: "data", equals: "{{text}}" },
      },
    };
    expect(await transport.dispatch(bad, {})).toEqual({
      status: "failed",
      reason: expect.stringContaining('no value for parameter "text"'),
    });
    expect(sim.received.filter((r) => r.message.op === "publish")).toEqual([]);
  });
});

describe("an emergency stop halts speech and animation too", () => {
  it("the robot stops speaking, stops its animation and stands still; the cut-off say is never completed", async () => {
    const { sim, transport } = await setUp(200, 5000);
    const robot = pluginRobot(nao, transport);
    await transport.dispatch(action("walk_forward"), { speed: 0.3 });
    const say = transport.dispatch({ ...action("say_text"), timeout: 1500 }, { text: "a long speech that is cut off" });
    void transport.dispatch(action("play_animation_hey"), {});
    await expect.poll(() => sim.state.speaking).toBe("a long speech that is cut off");
    await expect.poll(() => sim.state.animation).not.toBeNull();
    robot.halt();
    await expect.poll(() => sim.state).toMatchObject({ speaking: null, animation: null, velocity: { linear: 0 } });
    expect(sim.state.lastSaid).toBeNull();
    expect((await say).status).toBe("timed_out");
  });
});
