import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { audioPlayer, loadPlugin, portability, resolveAction, type Plugin } from "./index";

const plugin = (file: string) => {
  const loaded = loadPlugin(file, readFileSync(`plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
  return loaded.value;
};

const SOUND = { fileId: "f1", name: "chime.wav", sha256: "a".repeat(64), durationMs: 1500 };
const simulated = plugin("simulated.json");
/** The simulated robot, said to be unable to play files after all. */
const declaredUnable: Plugin = {
  ...simulated,
  abstract: Object.fromEntries(Object.entries(simulated.abstract ?? {}).filter(([id]) => id !== "play_audio")),
  unsupported: [{ action: "play_audio", reason: "no speaker" }],
};

describe("who plays a Play audio action", () => {
  it.each<[string, Plugin | null, "robot" | "browser"]>([
    ["the simulated robot, whose plugin maps play_audio", simulated, "robot"],
    ["NAO6, whose plugin has no way to play a file", plugin("nao6-ros2.json"), "browser"],
    ["Pepper", plugin("pepper-ros2.json"), "browser"],
    ["TurtleBot3, which has no speaker", plugin("turtlebot3-burger.json"), "browser"],
    ["a plugin that lists play_audio as unsupported", declaredUnable, "browser"],
    ["no robot chosen yet", null, "browser"],
  ])("%s: the %s", (_, robot, player) => {
    expect(audioPlayer(robot)).toBe(player);
  });

  it("the robot receives the file's name, hash and length through its binding", () => {
    const resolved = resolveAction(simulated, "play_audio", SOUND);
    expect(resolved).toMatchObject({
      status: "supported",
      action: { id: "play_audio" },
      parameters: { name: "chime.wav", sha256: SOUND.sha256, durationMs: 1500 },
    });
  });

  it("a file whose length is unknown is sent with length 0", () => {
    const { durationMs: _, ...unknownLength } = SOUND;
    expect(resolveAction(simulated, "play_audio", unknownLength)).toMatchObject({ parameters: { durationMs: 0 } });
  });

  it.each<[string, Record<string, unknown>, string]>([
    ["no file chosen", { name: "chime.wav", sha256: SOUND.sha256 }, "fileId"],
    ["a hash that is not SHA-256", { ...SOUND, sha256: "abc" }, "sha256"],
  ])("%s is a parameter problem on any robot, naming %s", (_, parameters, named) => {
    for (const robot of [simulated, plugin("nao6-ros2.json")]) {
      const resolved = resolveAction(robot, "play_audio", parameters);
      expect(resolved.status).toBe("parameter_problems");
      expect(JSON.stringify(resolved)).toContain(named);
    }
  });

  it("the portability report says who plays it", () => {
    const experiment = { steps: [{ actions: [{ id: "a", type: "play_audio", parameters: SOUND }] }] };
    expect(portability(experiment, simulated).actions[0]).toMatchObject({ status: "supported", by: "robot" });
    expect(portability(experiment, plugin("nao6-ros2.json")).actions[0]).toMatchObject({
      status: "supported",
      by: "browser",
    });
  });
});
