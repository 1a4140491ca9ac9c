import { describe, expect, it } from "vitest";
import { robotPreference, replayBusy, robotClaimed, runsPlugin } from "./registry";

const nao = (id: string) => ({ id, name: `NAO ${id}`, pluginRobotId: "nao6-ros2" });
const sim = (id: string) => ({ id, name: `Simulated ${id}`, pluginRobotId: null });
const pepper = { id: "p", name: "Pepper", pluginRobotId: "pepper-ros2" };

describe("choosing a robot for a trial", () => {
  it.each([
    ["the plugin's own robot before a simulated one", [sim("s1"), nao("a")], "nao6-ros2", [], "a"],
    ["the next free one when the first is held", [nao("a"), nao("b")], "nao6-ros2", ["a"], "b"],
    ["a simulated robot for any plugin", [pepper, sim("s1")], "turtlebot3-burger", [], "s1"],
    ["a second simulated robot when the first is held", [sim("s1"), sim("s2")], "nao6-ros2", ["s1"], "s2"],
    ["a held one when every fitting robot is held (its start waits)", [pepper, nao("a")], "nao6-ros2", ["a"], "a"],
    ["the plugin's own held robot before a held simulated one", [sim("s1"), nao("a")], "nao6-ros2", ["a", "s1"], "a"],
    ["none of another plugin", [pepper], "nao6-ros2", [], null],
  ])("%s", (_, available, robotId, held, expected) => {
    expect(robotPreference(available, robotId, new Set(held))[0]?.id ?? null).toBe(expected);
  });

  it("orders every fitting robot, so a runtime that finds one claimed elsewhere takes the next", () => {
    const order = robotPreference(
      [sim("s1"), nao("a"), pepper, nao("b"), sim("s2")],
      "nao6-ros2",
      new Set(["a", "s2"]),
    );
    expect(order.map((r) => r.id)).toEqual(["b", "s1", "a", "s2"]);
  });

  it("a simulated robot runs every plugin, a real one only its own", () => {
    expect(runsPlugin(sim("s"), "pepper-ros2")).toBe(true);
    expect(runsPlugin(nao("a"), "pepper-ros2")).toBe(false);
  });
});

describe("the words when a robot is busy", () => {
  it.each([
    ["live trial", 'The simulated robot "Sim 1" is running another trial; replay when it is free.'],
    ["starting trial", 'The simulated robot "Sim 1" is running another trial; replay when it is free.'],
    ["open trial", 'The simulated robot "Sim 1" is running another trial; replay when it is free.'],
    ["replay", 'The simulated robot "Sim 1" is playing another replay; replay when it is free.'],
    ["elsewhere", 'The simulated robot "Sim 1" is busy with another trial or replay; replay when it is free.'],
  ] as const)("a replay refused while %s holds the robot", (holder, words) => {
    expect(replayBusy("Sim 1", holder)).toBe(words);
  });

  it.each([
    ["starting trial", "another live trial (a trial that is starting now)"],
    ["replay", "a replay of a finished trial"],
    ["open trial", "another live trial (a trial open in this runtime)"],
    ["elsewhere", "a replay, or a trial open in another runtime"],
  ] as const)("a start refused while %s holds the robot", (holder, words) => {
    expect(robotClaimed("Sim 1", holder)).toContain(`"Sim 1" is being driven by ${words}`);
  });
});
