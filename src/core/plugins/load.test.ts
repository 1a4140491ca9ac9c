import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, outgoingFor, parsePluginIndex, parseRepository, resolveAction, unavailableActions } from "./index";

const fixtures = "tests/fixtures/hristudio-plugins";
const read = (path: string) => readFileSync(path, "utf8");

describe("HRIStudio files load unmodified", () => {
  it("loads the fixture NAO6 plugin", () => {
    const result = loadPlugin("nao6-ros2.json", read(`${fixtures}/plugins/nao6-ros2.json`));
    expect(result.ok ? [] : result.errors).toEqual([]);
    if (result.ok) expect(result.value.actions).toHaveLength(20);
  });
  it("parses repository.json and plugins/index.json", () => {
    const repo = parseRepository("repository.json", read(`${fixtures}/repository.json`));
    expect(repo.ok && repo.value.id).toBe("hristudio-official");
    const index = parsePluginIndex("plugins/index.json", read(`${fixtures}/plugins/index.json`));
    expect(index.ok && index.value).toEqual(["turtlebot3-burger.json", "turtlebot3-waffle.json", "nao6-ros2.json"]);
  });
});

describe("bad repository files", () => {
  it.each([
    [
      "plugins/index.json",
      '["../../etc/passwd.json"]',
      [{ path: "/0", reason: "must be a plugin file name ending in .json, without folders" }],
    ],
    [
      "plugins/index.json",
      '["a.json", "a.json"]',
      [{ path: "", reason: "lists the same value twice (numbers 1 and 2)" }],
    ],
    ["plugins/index.json", '{"plugins": []}', [{ path: "", reason: "must be a list" }]],
    ["repository.json", '{"name": "x"}', [{ path: "/id", reason: "is required but missing" }]],
    [
      "repository.json",
      '{"id": "x", "name": "x", "trust": "total"}',
      [{ path: "/trust", reason: 'must be one of: "official", "verified", "community"' }],
    ],
  ])("%s %s", (file, text, expected) => {
    const result = file === "repository.json" ? parseRepository(file, text) : parsePluginIndex(file, text);
    expect(result.ok ? [] : result.errors).toEqual(expected.map((e) => ({ file, code: "schema", ...e })));
  });

  it("gives line and column for invalid JSON", () => {
    expect(parsePluginIndex("plugins/index.json", '[\n  "a.json"\n  "b.json"\n]')).toEqual({
      ok: false,
      errors: [
        {
          file: "plugins/index.json",
          path: "",
          code: "invalid_json",
          reason: 'invalid JSON: expected "," or "]" in a list, found "\\""',
          line: 3,
          column: 3,
        },
      ],
    });
  });
});

const hristudio = (file: string) => {
  const loaded = loadPlugin(file, read(`${fixtures}/plugins/${file}`));
  if (!loaded.ok) throw new Error(loaded.errors.map((e) => `${e.path}: ${e.reason}`).join("\n"));
  return loaded.value;
};

describe("an action the platform cannot carry out loads as unsupported, with its reason", () => {
  it.each([
    ["nao6-ros2.json", []],
    ["turtlebot3-burger.json", []],
    [
      "turtlebot3-waffle.json",
      [
        ["capture_image", "/actions/2/ros2/payloadMapping/transformFn", /saves a picture from the robot's camera/],
        ["scan_environment", "/actions/3/ros2/payloadMapping/transformFn", /records laser scans/],
        ["follow_wall", "/actions/5/ros2/payloadMapping/transformFn", /follows a wall .* closed loop/],
      ],
    ],
  ] as const)("%s loads whole", (file, expected) => {
    const unavailable = unavailableActions(hristudio(file));
    expect(unavailable.map((u) => [u.actionId, u.path])).toEqual(expected.map(([id, path]) => [id, path]));
    unavailable.forEach((u, i) => expect(u.reason).toMatch(expected[i]![2]));
  });

  it("an experiment's action that needs one is unsupported with that reason, never sent", () => {
    const waffle = hristudio("turtlebot3-waffle.json");
    const resolution = resolveAction(waffle, "turtlebot3-waffle.follow_wall", {
      side: "left",
      distance: 0.3,
      duration: 10,
    });
    expect(resolution).toEqual({
      status: "unsupported",
      reason: expect.stringMatching(/^turtlebot3-waffle's "Follow Wall" cannot run: it follows a wall/),
    });
    const follow = waffle.actions.find((a) => a.id === "follow_wall")!;
    expect(outgoingFor(follow, {}, waffle)).toEqual({ kind: "none", reason: expect.stringMatching(/cannot run/) });
  });
});

/** A small plugin with one action whose dispatch block is changed per case. */
const withDispatch = (ros2: Record<string, unknown>, more: Record<string, unknown>[] = []) =>
  JSON.stringify({
    robotId: "bot",
    name: "Bot",
    version: "1.0.0",
    pluginApiVersion: "1.0",
    actions: [
      { id: "act", name: "Act", category: "movement", parameterSchema: { type: "object", properties: {} }, ros2 },
      ...more,
    ],
  });

describe("the loader's one pass", () => {
  it.each([
    [
      "a ROS 2 action goal without a message type, and a missing name elsewhere",
      withDispatch({ action: "/navigate_to_pose", payloadMapping: { type: "static", payload: {} } }, [
        { id: "b", category: "x", parameterSchema: { type: "object", properties: {} } },
      ]),
      [
        ["/actions/0/ros2/messageType", "is required but missing"],
        ["/actions/1/name", "is required but missing"],
      ],
    ],
    [
      "a broken action beside a placeholder naming no parameter",
      withDispatch(
        {
          topic: "/say",
          messageType: "std_msgs/msg/String",
          payloadMapping: { type: "static", payload: { data: "{{text}}" } },
        },
        [{ id: "b", name: "B", category: "x", timeout: -1, parameterSchema: { type: "object", properties: {} } }],
      ),
      [
        ["/actions/1/timeout", "must be at least 1"],
        ["/actions/0/ros2/payloadMapping/payload/data", '{{text}} names no parameter of action "act"'],
      ],
    ],
    [
      "a bad action type",
      withDispatch({
        action: "/spin",
        actionType: "spin",
        messageType: "std_msgs/msg/Empty",
        payloadMapping: { type: "static", payload: {} },
      }),
      [["/actions/0/ros2/actionType", "must match the pattern ^[A-Za-z][A-Za-z0-9_]*/(action/)?[A-Z][A-Za-z0-9_]*$"]],
    ],
  ])("%s: every problem at once", (_, text, expected) => {
    const result = loadPlugin("bot.json", text);
    expect(result.ok ? [] : result.errors.map((e) => [e.path, e.reason])).toEqual(expected);
  });

  it.each([
    [
      "a transform nobody wrote",
      {
        topic: "/x",
        messageType: "std_msgs/msg/String",
        payloadMapping: { type: "transform", transformFn: "transformToDance" },
      },
      'it needs the transform "transformToDance", which this platform does not have',
    ],
    [
      "a turn with no top turning speed declared",
      {
        topic: "/cmd_vel",
        messageType: "geometry_msgs/msg/Twist",
        payloadMapping: { type: "transform", transformFn: "transformToRotation" },
      },
      'it turns at a fraction of the robot\'s top turning speed, and the plugin declares none (the "angular" maximum of a transformToTwist action)',
    ],
    [
      "a goal whose action type we cannot tell",
      { action: "/dock", messageType: "std_msgs/msg/Empty", payloadMapping: { type: "static", payload: {} } },
      "it sends a goal to the ROS 2 action /dock, but its plugin names no actionType and its goal message std_msgs/msg/Empty is not one whose action we know",
    ],
    [
      "a goal that names its action type",
      {
        action: "/dock",
        actionType: "nav2_msgs/action/DockRobot",
        messageType: "x/msg/Y",
        payloadMapping: { type: "static", payload: {} },
      },
      null,
    ],
  ])("%s loads, the action marked accordingly", (_, ros2, reason) => {
    const result = loadPlugin("bot.json", withDispatch(ros2));
    expect(result.ok ? [] : result.errors).toEqual([]);
    if (result.ok) expect(unavailableActions(result.value).map((u) => u.reason)).toEqual(reason ? [reason] : []);
  });
});

describe("checking the parts the schema found sound never trips on the broken ones", () => {
  it("loads every one-field corruption of the Waffle file without throwing", () => {
    const base = JSON.parse(read(`${fixtures}/plugins/turtlebot3-waffle.json`));
    const paths = (value: unknown, at: Array<string | number> = []): Array<Array<string | number>> => [
      at,
      ...(value && typeof value === "object"
        ? Object.entries(value).flatMap(([k, v]) => paths(v, [...at, Array.isArray(value) ? Number(k) : k]))
        : []),
    ];
    let loaded = 0;
    for (const path of paths(base).filter((p) => p.length)) {
      for (const junk of [null, 1, "x", [], {}, [null]]) {
        const document = structuredClone(base);
        const parent = path.slice(0, -1).reduce((o, k) => o[k], document);
        parent[path.at(-1)!] = junk;
        const result = loadPlugin("waffle.json", JSON.stringify(document));
        if (result.ok) unavailableActions(result.value);
        loaded++;
      }
    }
    expect(loaded).toBeGreaterThan(1000);
  });
});
