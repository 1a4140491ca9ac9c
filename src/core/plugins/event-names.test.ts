import { describe, expect, it } from "vitest";
import type { Plugin } from "./types";
import { eventName, eventNamesOf, NO_EVENT_NAMES } from "./event-names";

const plugin = {
  events: [{ id: "head_touched", name: "Head touched" }],
} as unknown as Plugin;

describe("what a robot's event is called", () => {
  it.each([
    ["a declared event: its plugin's name", "head_touched", eventNamesOf(plugin), "Head touched"],
    ["an event the plugin does not declare: its id", "heard_ready", eventNamesOf(plugin), "heard_ready"],
    ["without a plugin: its id", "head_touched", eventNamesOf(null), "head_touched"],
    ["with no names at all: its id", "head_touched", NO_EVENT_NAMES, "head_touched"],
  ])("%s", (_, id, names, name) => {
    expect(eventName(id, names)).toBe(name);
  });
});
