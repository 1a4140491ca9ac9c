import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { loadPlugin, type Plugin } from "../plugins";
import { libraryEntries, searchLibrary, type LibraryEntry } from "./library";

function plugin(path: string): Plugin {
  const loaded = loadPlugin(path, readFileSync(path, "utf8"));
  if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
  return loaded.value;
}

const names = (entries: LibraryEntry[]) => entries.map((e) => e.block.name);
const variantsOf = (entries: LibraryEntry[], type: string) =>
  entries.find((e) => e.block.type === type)?.variants.map((v) => v.name);
const entryOf = (entries: LibraryEntry[], type: string) =>
  entries.find((e) => e.block.type === type || e.variants.some((v) => v.type === type))?.block.type;

const FILES = [
  "plugins/nao6-ros2.json",
  "plugins/pepper-ros2.json",
  "plugins/simulated.json",
  "plugins/turtlebot3-burger.json",
  // HRIStudio's own file, with no abstract mapping (its TurtleBot files do not load: actions without a topic).
  "tests/fixtures/hristudio-plugins/plugins/nao6-ros2.json",
];

describe("the library, one entry per capability", () => {
  it.each(FILES)("%s: no two entries share a name, and every action is offered exactly once", (file) => {
    const p = plugin(file);
    const entries = libraryEntries(p);
    const shown = names(entries).map((n) => n.toLowerCase());
    expect(new Set(shown).size).toBe(shown.length);
    const offered = entries.flatMap((e) => [e.block.type, ...e.variants.map((v) => v.type)]);
    expect(new Set(offered).size).toBe(offered.length);
    for (const action of p.actions) expect(offered).toContain(`${p.robotId}.${action.id}`);
  });

  // [robot, abstract block, its variants]: the look-alikes a user met, each now under its block.
  it.each([
    ["nao6-ros2", "stop", ["Stop"]],
    ["nao6-ros2", "look_down", ["Look Down"]],
    ["nao6-ros2", "nod", ["Yes (Nod)"]],
    ["nao6-ros2", "head_shake", ["No (Head Shake)"]],
    ["nao6-ros2", "play_animation", ["Play Animation"]],
    ["nao6-ros2", "wave", ["Hey"]],
    ["nao6-ros2", "say", ["Say Text"]],
    ["nao6-ros2", "posture", ["Rest", "Stand", "Sit", "Crouch"]],
    ["nao6-ros2", "move", ["Walk Forward", "Walk Backward", "Turn Left", "Turn Right"]],
    ["turtlebot3-burger", "stop", ["Stop"]],
    ["turtlebot3-burger", "say", []],
    ["simulated", "say", ["Say"]],
    ["simulated", "wave", []],
  ])("%s: %s has the variants %j", (robot, type, expected) => {
    expect(variantsOf(libraryEntries(plugin(`plugins/${robot}.json`)), type)).toEqual(expected);
  });

  // [file, robot action type, the entry it is offered under]
  it.each([
    ["plugins/nao6-ros2.json", "nao6-ros2.play_animation_bow", "nao6-ros2.play_animation_bow"],
    ["plugins/nao6-ros2.json", "nao6-ros2.stand_init", "nao6-ros2.stand_init"],
    ["plugins/nao6-ros2.json", "nao6-ros2.say_with_emotion", "nao6-ros2.say_with_emotion"],
    // One action for several blocks (wave, nod, head shake, look down) is a capability of its own.
    ["plugins/simulated.json", "simulated.gesture", "simulated.gesture"],
    ["plugins/turtlebot3-burger.json", "turtlebot3-burger.beep", "turtlebot3-burger.beep"],
    // A file with no abstract mapping: a same-named action still joins the block it looks like.
    ["tests/fixtures/hristudio-plugins/plugins/nao6-ros2.json", "nao6-ros2.stop_walking", "stop"],
    [
      "tests/fixtures/hristudio-plugins/plugins/nao6-ros2.json",
      "nao6-ros2.play_animation_yes",
      "nao6-ros2.play_animation_yes",
    ],
  ])("%s: %s is offered under %s", (file, type, under) => {
    expect(entryOf(libraryEntries(plugin(file)), type)).toBe(under);
  });

  it("without a robot, offers the control and abstract blocks, none with variants", () => {
    const entries = libraryEntries(null);
    expect(names(entries)).toEqual(expect.arrayContaining(["Record answer", "Say", "Nod", "Stop"]));
    expect(entries.every((e) => e.variants.length === 0)).toBe(true);
  });
});

describe("searching the library", () => {
  const entries = libraryEntries(plugin("plugins/nao6-ros2.json"));
  // [query, entries shown with their variants, and which are opened to show a matching variant]
  it.each([
    ["", undefined, false],
    ["nod", { nod: ["Yes (Nod)"] }, true],
    ["yes", { nod: ["Yes (Nod)"] }, true],
    ["walk backward", { move: ["Walk Backward"] }, true],
    ["bow", { "nao6-ros2.play_animation_bow": [] }, false],
    // The robot's own stops (what an emergency stop sends) are actions a design may use too.
    ["STOP", { stop: ["Stop"], "nao6-ros2.stop_speech": [], "nao6-ros2.stop_animation": [] }, true],
    ["no such thing", {}, false],
  ])("%j", (query, expected, open) => {
    const shown = searchLibrary(entries, query);
    if (!expected) return expect(shown.length).toBe(entries.length);
    expect(Object.fromEntries(shown.map((e) => [e.block.type, e.variants.map((v) => v.name)]))).toEqual(expected);
    // Opened: an entry shown for a matching variant; one that matches by its own name has none to open.
    expect(shown.every((e) => e.open === (open && e.variants.length > 0))).toBe(true);
  });
});
