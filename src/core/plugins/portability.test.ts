import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { STORYTELLER_STEPS } from "../../server/seed/storyteller";
import { cannotStart, eventProblems, loadPlugin, type Plugin, portability, type PortableExperiment } from "./index";

const plugin = (file: string) => {
  const loaded = loadPlugin(file, readFileSync(`plugins/${file}`, "utf8"));
  if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
  return loaded.value;
};

// The Interactive Storyteller as the demo seed writes it.
const storyteller: PortableExperiment = {
  steps: STORYTELLER_STEPS.map((step) => ({
    id: step.key,
    actions: step.actions.map((a, i) => ({ id: `${step.key}-${i}`, type: a.type, parameters: a.parameters })),
  })),
};

const summary = (file: string) =>
  portability(storyteller, plugin(file)).actions.map(
    (a) => `${a.type}: ${a.status}${a.pluginAction ? ` (${a.pluginAction})` : ""}${a.reason ? ` - ${a.reason}` : ""}`,
  );

describe("the Interactive Storyteller on each first-party robot", () => {
  const robotRows = (via: Record<string, string>) => [
    `say: supported (${via.say})`,
    `wave: supported (${via.wave})`,
    `say: supported (${via.say})`,
    `look_down: supported (${via.look_down})`,
    "pause: supported",
    `say: supported (${via.say})`,
    "record_answer: supported",
    "branch: supported",
    `say: supported (${via.say})`,
    `nod: supported (${via.nod})`,
    "end_trial: supported",
    `say: supported (${via.say})`,
    `head_shake: supported (${via.head_shake})`,
    "end_trial: supported",
  ];
  const naoqi = {
    say: "say_text",
    wave: "play_animation_hey",
    look_down: "look_down",
    nod: "play_animation_yes",
    head_shake: "play_animation_no",
  };

  it("NAO6 runs all of it", () => expect(summary("nao6-ros2.json")).toEqual(robotRows(naoqi)));
  it("Pepper runs all of it", () => expect(summary("pepper-ros2.json")).toEqual(robotRows(naoqi)));
  it("the simulated robot runs all of it", () =>
    expect(summary("simulated.json")).toEqual(
      robotRows({ say: "say", wave: "gesture", look_down: "gesture", nod: "gesture", head_shake: "gesture" }),
    ));

  it("TurtleBot3 cannot speak or gesture, and says why", () => {
    const report = portability(storyteller, plugin("turtlebot3-burger.json"));
    expect(report.portable).toBe(false);
    expect(summary("turtlebot3-burger.json")).toEqual([
      "say: unsupported - The TurtleBot3 has no speaker; its buzzer can only beep (use turtlebot3-burger.beep).",
      "wave: unsupported - The TurtleBot3 has no arms.",
      "say: unsupported - The TurtleBot3 has no speaker; its buzzer can only beep (use turtlebot3-burger.beep).",
      "look_down: unsupported - The TurtleBot3 has no head or tilting camera.",
      "pause: supported",
      "say: unsupported - The TurtleBot3 has no speaker; its buzzer can only beep (use turtlebot3-burger.beep).",
      "record_answer: supported",
      "branch: supported",
      "say: unsupported - The TurtleBot3 has no speaker; its buzzer can only beep (use turtlebot3-burger.beep).",
      "nod: unsupported - The TurtleBot3 has no head.",
      "end_trial: supported",
      "say: unsupported - The TurtleBot3 has no speaker; its buzzer can only beep (use turtlebot3-burger.beep).",
      "head_shake: unsupported - The TurtleBot3 has no head.",
      "end_trial: supported",
    ]);
  });
});

describe("portability of other actions", () => {
  const one = (file: string, type: string, parameters: Record<string, unknown>) =>
    portability({ steps: [{ actions: [{ id: "a", type, parameters }] }] }, plugin(file)).actions[0];

  it.each([
    ["nao6-ros2.json", "posture", { posture: "sit" }, "supported", "sit"],
    ["pepper-ros2.json", "posture", { posture: "sit" }, "parameter_problems", undefined],
    ["nao6-ros2.json", "move", { direction: "forward", speed: 0.3 }, "supported", "walk_forward"],
    ["turtlebot3-burger.json", "move", { direction: "forward", speed: 0.3 }, "parameter_problems", "move_forward"],
    ["turtlebot3-burger.json", "stop", {}, "supported", "stop"],
    ["turtlebot3-burger.json", "turtlebot3-burger.beep", { pattern: 2 }, "supported", "beep"],
    ["turtlebot3-burger.json", "nao6-ros2.play_animation_bow", {}, "unsupported", undefined],
    ["nao6-ros2.json", "nao6-ros2.play_animation_bow", {}, "supported", "play_animation_bow"],
    ["simulated.json", "play_animation", { name: "dance" }, "supported", "play_animation"],
  ])("%s %s %j is %s", (file, type, parameters, status, pluginAction) => {
    const row = one(file, type, parameters);
    expect(row?.status).toBe(status);
    expect(row?.pluginAction).toBe(pluginAction);
  });

  it("names the parameter a robot cannot meet", () => {
    expect(one("turtlebot3-burger.json", "move", { direction: "forward", speed: 0.3 })?.problems).toEqual([
      { parameter: "speed", message: '"Speed (m/s)" must be at most 0.22' },
    ]);
    expect(one("pepper-ros2.json", "posture", { posture: "sit" })?.problems).toEqual([
      { parameter: "posture", message: '"posture" "sit" is not supported by this robot (supported: "stand", "rest")' },
    ]);
  });
});

describe("events a robot cannot report", () => {
  const robot = {
    robotId: "r",
    name: "Robot",
    version: "1.0.0",
    pluginApiVersion: "1.0",
    actions: [],
    events: [
      {
        id: "head_touched",
        name: "Head touched",
        topic: "/head_touch",
        messageType: "naoqi_bridge_msgs/msg/HeadTouch",
        when: { kind: "pressed", field: "state", equals: 1 },
      },
    ],
  } as Plugin;
  const senseless = { ...robot, events: undefined };

  it.each<[string, string[], Plugin, string[]]>([
    ["nothing awaited", [], robot, []],
    ["an event it declares", ["head_touched"], robot, []],
    [
      "one it does not",
      ["head_touched", "heard_ready"],
      robot,
      ['Robot (plugin 1.0.0) does not sense "heard_ready" (it senses: head_touched)'],
    ],
    [
      "a robot that senses nothing, the same id twice",
      ["head_touched", "head_touched"],
      senseless,
      ['Robot (plugin 1.0.0) does not sense "head_touched" (it senses: none)'],
    ],
  ])("%s", (_what, ids, plugin, expected) => {
    expect(eventProblems(ids, plugin)).toEqual(expected);
  });
});

describe("the events a wait needs the robot to sense", () => {
  const sensing: Plugin = {
    ...plugin("simulated.json"),
    events: [
      {
        id: "head_touched",
        name: "Head touched",
        topic: "/touch",
        messageType: "std_msgs/msg/Bool",
        when: { kind: "pressed", field: "data", equals: true },
      },
    ],
  };
  const waiting = (events: string[]): PortableExperiment => ({
    steps: [
      {
        name: "Start",
        actions: [
          {
            id: "wait",
            type: "wait_for",
            parameters: { events: events.map((event, i) => ({ id: `e${i}`, event, after: { to: "next" } })) },
          },
        ],
      },
    ],
  });

  it.each<[string, string[], string[]]>([
    ["an event the plugin declares", ["head_touched"], []],
    [
      "an event it does not, named once",
      ["head_touched", "heard_word", "heard_word"],
      [`${sensing.name} (plugin ${sensing.version}) does not sense "heard_word" (it senses: head_touched)`],
    ],
  ])("%s", (_, events, expected) => {
    expect(eventProblems(events, sensing)).toEqual(expected);
  });

  it("a wait for an event the robot cannot sense is unsupported, so a trial cannot start", () => {
    expect(portability(waiting(["head_touched"]), sensing).portable).toBe(true);
    expect(portability(waiting(["heard_word"]), sensing).actions[0]).toMatchObject({
      status: "unsupported",
      by: "runtime",
    });
    expect(cannotStart(waiting(["heard_word"]), sensing)).toContain(
      `step 1 (Start), "wait_for": ${sensing.name} (plugin ${sensing.version}) does not sense "heard_word"`,
    );
  });
});

describe("portability of each condition's variant", () => {
  // The shared design beeps; one condition's variant of the action speaks, another's whole step does.
  const varied: PortableExperiment = {
    steps: [
      {
        id: "s",
        actions: [
          {
            id: "go",
            type: "turtlebot3-burger.beep",
            parameters: { pattern: 2 },
            variants: { Talkative: { type: "say", parameters: { text: "Here I come" } } },
          },
        ],
        variants: { Polite: { actions: [{ id: "hi", type: "say", parameters: { text: "Hello" } }] } },
      },
    ],
  };

  it.each<[string, string[]]>([
    [
      "turtlebot3-burger.json",
      ["go turtlebot3-burger.beep supported", "go say unsupported Talkative", "hi say unsupported Polite"],
    ],
    [
      "nao6-ros2.json",
      ["go turtlebot3-burger.beep unsupported", "go say supported Talkative", "hi say supported Polite"],
    ],
  ])("on %s: each action as each condition runs it", (file, rows) => {
    const report = portability(varied, plugin(file));
    expect(report.actions.map((a) => [a.actionId, a.type, a.status, a.condition].filter(Boolean).join(" "))).toEqual(
      rows,
    );
    expect(report.portable).toBe(false);
  });
});
