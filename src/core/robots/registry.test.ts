import { describe, expect, it } from "vitest";
import { chooseRobot, parseSecretReference, runsPlugin } from "./registry";

describe("secret references", () => {
  it.each([
    ["env:NAO_A_SSH_PASSWORD", { kind: "env", name: "NAO_A_SSH_PASSWORD" }],
    ["file:/etc/hristudio/nao-a.key", { kind: "file", path: "/etc/hristudio/nao-a.key" }],
    ["file:/c:/odd:name", { kind: "file", path: "/c:/odd:name" }],
  ])("%s is read as a reference", (reference, expected) => {
    expect(parseSecretReference(reference)).toEqual(expected);
  });

  it.each([
    ["a plain password", "hunter2", "must be env:VARIABLE or file:/path"],
    ["a password after env:", "env:p@ss word", "must name an environment variable"],
    ["a relative key path", "file:keys/nao.key", "absolute path"],
    ["nothing after the kind", "env:", "must name an environment variable"],
  ])("%s is refused", (_, reference, reason) => {
    const parsed = parseSecretReference(reference);
    expect("error" in parsed && parsed.error).toContain(reason);
  });
});

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
    expect(chooseRobot(available, robotId, new Set(held))?.id ?? null).toBe(expected);
  });

  it("a simulated robot runs every plugin, a real one only its own", () => {
    expect(runsPlugin(sim("s"), "pepper-ros2")).toBe(true);
    expect(runsPlugin(nao("a"), "pepper-ros2")).toBe(false);
  });
});
