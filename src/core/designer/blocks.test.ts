import { describe, expect, it } from "vitest";
import { blockFor, library, RUN_TOGETHER } from "./blocks";

describe("the block library", () => {
  it("offers the control blocks, run together, and the abstract actions even without a robot", () => {
    const types = library(null).map((b) => b.type);
    expect(types).toEqual(
      expect.arrayContaining([
        "wizard_instruction",
        "record_answer",
        "branch",
        "end_trial",
        "run_together",
        "say",
        "wave",
        "pause",
      ]),
    );
  });

  it("offers Play audio on any robot, saying who plays it", () => {
    expect(blockFor("play_audio", null)).toMatchObject({
      name: "Play audio",
      category: "speech",
      description: "One of the study's sounds, played by the robot where it can, otherwise by the wizard's browser.",
    });
  });

  it("never takes run together for an action: it is a tool that links actions", () => {
    expect(blockFor(RUN_TOGETHER.type, null)).toBeUndefined();
  });
});
