import { describe, expect, it } from "vitest";
import nao6 from "../../../plugins/nao6-ros2.json";
import type { Plugin } from "../plugins";
import { actionName, actionNamesOf, blockName, readableValue } from "./action-name";

const names = actionNamesOf(nao6 as unknown as Plugin);

describe("an action's display name", () => {
  it.each([
    [
      "its label, when the researcher gave one",
      { type: "say", name: "Greeting", parameters: { text: "Hello" } },
      "Greeting",
    ],
    ["a blank label counts as none", { type: "wave", name: "  ", parameters: {} }, "Wave"],
    [
      "speech: the block and its text, cut at a word",
      { type: "say", name: "", parameters: { text: "Hi! I am Nao, and today I will tell you a story." } },
      "Say: Hi! I am Nao, and today I will…",
    ],
    ["short speech whole", { type: "say", parameters: { text: "Hello  there" } }, "Say: Hello there"],
    ["a gesture without settings", { type: "wave", parameters: {} }, "Wave"],
    ["a pause with its length", { type: "pause", parameters: { seconds: 3 } }, "Pause 3 s"],
    ["a pause of part of a second", { type: "pause", parameters: { seconds: 0.5 } }, "Pause 0.5 s"],
    [
      "a question with its prompt",
      { type: "record_answer", parameters: { prompt: "Which planet did Kai visit on her mission?", options: [] } },
      "Record answer: Which planet did Kai visit on…",
    ],
    [
      "a question without a prompt",
      { type: "record_answer", parameters: { prompt: "", options: [] } },
      "Record answer",
    ],
    [
      "a sound by its file's name, as written",
      { type: "play_audio", parameters: { fileId: "f", name: "chime_2.wav", sha256: "a".repeat(64) } },
      "Play audio: chime_2.wav",
    ],
    ["a sound not chosen yet", { type: "play_audio", parameters: {} }, "Play audio"],
    ["a posture in words", { type: "posture", parameters: { posture: "sit" } }, "Posture: Sit"],
    ["a direction in words", { type: "move", parameters: { direction: "turn_left", speed: 0.1 } }, "Move: Turn left"],
    [
      "an animation by its name, not its path",
      { type: "play_animation", parameters: { name: "animations/Stand/Gestures/Hey_1" } },
      "Play animation: Hey 1",
    ],
    [
      "a wizard instruction with its text",
      { type: "wizard_instruction", parameters: { text: "Hand the participant the card." } },
      "Wizard instruction: Hand the participant the card.",
    ],
    ["a branch", { type: "branch", parameters: { targets: {} } }, "Branch"],
    ["the end", { type: "end_trial", parameters: {} }, "End trial"],
    ["the robot's own action, as its plugin names it", { type: "nao6-ros2.play_animation_bow", parameters: {} }, "Bow"],
    [
      "the robot's own speech with its text",
      { type: "nao6-ros2.say_with_emotion", parameters: { text: "Great!", emotion: "happy" } },
      "Say with Emotion: Great!",
    ],
    [
      "a robot action no plugin names, in words",
      { type: "pepper-ros2.play_animation_bow", parameters: {} },
      "Play animation bow",
    ],
    ["an unscripted action without parameters", { type: "nod" }, "Nod"],
    ["a type nobody knows", { type: "dance_wildly", parameters: {} }, "Dance wildly"],
  ])("%s", (_, action, expected) => {
    expect(actionName(action, names)).toBe(expected);
  });

  it("knows the built-in blocks without a plugin", () => {
    expect(actionName({ type: "pause", parameters: { seconds: 2 } })).toBe("Pause 2 s");
    expect(blockName("record_answer")).toBe("Record answer");
    expect(actionNamesOf(null).say).toBe("Say");
  });
});

describe("a setting in words", () => {
  it.each([
    ["animations/Stand/Gestures/Hey_1", "Hey 1"],
    ["head_shake", "Head shake"],
    ["sit", "Sit"],
    ["Already Fine", "Already Fine"],
  ])("%s → %s", (value, expected) => {
    expect(readableValue(value)).toBe(expected);
  });
});
