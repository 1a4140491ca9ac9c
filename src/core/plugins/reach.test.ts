import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import {
  channelOf,
  loadPlugin,
  portability,
  unreachable,
  type Channels,
  type Reachable,
  type PluginAction,
} from "./index";

const plugin = (file: string) => {
  const loaded = loadPlugin(file, readFileSync(`plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
  return loaded.value;
};

const NONE: Channels = { rosbridge: false, simulator: false, ssh: false, http: false };
/** What `npm start` gives with no robot settings: the simulated NAO6's rosbridge and SSH. */
const DEMO: Channels = { rosbridge: true, simulator: true, ssh: true, http: false };
const ROSBRIDGE_ONLY: Channels = { ...NONE, rosbridge: true, simulator: true };

const SSH_NEEDED =
  "it needs SSH to the robot, and this server has no SSH address for it: set HRI_ROBOT_SSH_HOST (see docs/robot-setup.md)";
const ROSBRIDGE_NEEDED =
  "it needs the robot's rosbridge, and this server has no address for it: set HRI_ROSBRIDGE_URL (see docs/robot-setup.md)";
const SIMULATOR_NEEDED =
  "it needs the simulated robot, which this server is not running (npm start runs it when HRI_ROSBRIDGE_URL is not set)";

/** Each action of a first-party plugin that cannot run with these channels, and why. */
const blocked = (file: string, channels: Channels) =>
  Object.fromEntries(
    plugin(file).actions.flatMap((a) => {
      const why = unreachable(plugin(file), a, channels);
      return why ? [[a.id, why]] : [];
    }),
  );

const NAOQI = ["wake_up", "rest", "stand", "stand_init", "sit", "crouch"];
const only = (ids: string[], why: string) => Object.fromEntries(ids.map((id) => [id, why]));
const all = (file: string, why: string) =>
  only(
    plugin(file).actions.map((a) => a.id),
    why,
  );

describe("which actions this server can carry to the robot", () => {
  it.each<[string, Channels, Record<string, string>]>([
    ["nao6-ros2.json", DEMO, {}],
    ["nao6-ros2.json", ROSBRIDGE_ONLY, only(NAOQI, SSH_NEEDED)],
    ["nao6-ros2.json", { ...NONE, ssh: true }, all("nao6-ros2.json", ROSBRIDGE_NEEDED)],
    ["pepper-ros2.json", DEMO, {}],
    ["pepper-ros2.json", ROSBRIDGE_ONLY, only(["wake_up", "rest", "stand"], SSH_NEEDED)],
    ["turtlebot3-burger.json", ROSBRIDGE_ONLY, {}],
    ["turtlebot3-burger.json", NONE, all("turtlebot3-burger.json", ROSBRIDGE_NEEDED)],
    ["simulated.json", DEMO, {}],
    ["simulated.json", NONE, all("simulated.json", SIMULATOR_NEEDED)],
  ])("%s with %j", (file, channels, expected) => {
    expect(blocked(file, channels)).toEqual(expected);
  });

  const http = (httpBaseUrl?: string): Reachable => ({
    transport: "http",
    httpBaseUrl,
  });
  const naoqi = plugin("nao6-ros2.json").actions.find((a) => a.id === "sit")!;
  const plain = { id: "beep", name: "Beep" } as PluginAction;

  it.each<[string, Reachable, PluginAction | undefined, Channels, string | null]>([
    ["an HTTP robot whose plugin names its address", http("http://robot.local/api"), plain, NONE, null],
    ["an HTTP robot given its address by the server", http(), plain, { ...NONE, http: true }, null],
    [
      "an HTTP robot with no address",
      http(),
      plain,
      NONE,
      "it needs the robot's REST API, and neither its plugin nor this server gives the address: set HRI_ROBOT_HTTP_URL",
    ],
    ["an SSH robot, as a whole", { transport: "ssh" }, undefined, { ...NONE, ssh: true }, null],
    ["an SSH robot with no SSH address", { transport: "ssh" }, plain, ROSBRIDGE_ONLY, SSH_NEEDED],
    ["a NAOqi command on an HTTP robot", http("http://robot.local"), naoqi, { ...NONE, http: true }, SSH_NEEDED],
    ["a rosbridge robot, as a whole, with SSH only", {}, undefined, { ...NONE, ssh: true }, ROSBRIDGE_NEEDED],
  ])("%s", (_, robot, action, channels, why) => {
    expect(unreachable(robot, action, channels)).toBe(why);
  });

  it("names each action's way to the robot", () => {
    const nao = plugin("nao6-ros2.json");
    expect(nao.actions.map((a) => [a.id, channelOf(nao, a)]).filter(([, c]) => c !== "rosbridge")).toEqual(
      NAOQI.map((id) => [id, "ssh"]),
    );
    expect(channelOf(plugin("simulated.json"))).toBe("simulator");
  });

  it("the portability report calls an action this server cannot carry unsupported, and says why", () => {
    const experiment = {
      steps: [
        {
          actions: [
            { id: "a", type: "posture", parameters: { posture: "sit" } },
            { id: "b", type: "say", parameters: { text: "Hi" } },
          ],
        },
      ],
    };
    const nao = plugin("nao6-ros2.json");
    const rows = (channels?: Channels) =>
      portability(experiment, nao, channels).actions.map((a) => [a.status, a.pluginAction, a.reason]);
    expect(rows()).toEqual([
      ["supported", "sit", undefined],
      ["supported", "say_text", undefined],
    ]);
    expect(rows(DEMO)).toEqual(rows());
    expect(rows(ROSBRIDGE_ONLY)).toEqual([
      ["unsupported", "sit", SSH_NEEDED],
      ["supported", "say_text", undefined],
    ]);
    expect(portability(experiment, nao, ROSBRIDGE_ONLY).portable).toBe(false);
  });
});
