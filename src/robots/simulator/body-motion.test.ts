import { describe, expect, it } from "vitest";
import { anglesAt, GESTURE_SECONDS, gestureBegun, type Motion, postureChosen, still } from "./body-motion";

const stand = still("stand");
const waving = gestureBegun(stand, "wave", 2);
const sitting = postureChosen(stand, "sit", 2);

describe("the simulated body's joints (HeadYaw, HeadPitch, LShoulderPitch, RShoulderPitch)", () => {
  it.each<[string, Motion, number, number[]]>([
    ["standing still", stand, 5, [0, 0, 1.4, 1.4]],
    ["before a wave begins", waving, 1.9, [0, 0, 1.4, 1.4]],
    ["a wave at its height raises the right arm", waving, 2 + GESTURE_SECONDS / 2, [0, 0, 1.4, -0.6]],
    ["after the wave, back where the posture is", waving, 2 + GESTURE_SECONDS, [0, 0, 1.4, 1.4]],
    ["halfway to sitting", sitting, 2.5, [0, 0.1, 1.2, 1.2]],
    ["seated", sitting, 3, [0, 0.2, 1, 1]],
    ["an unknown posture holds the standing angles", still("kneel"), 1, [0, 0, 1.4, 1.4]],
  ])("%s", (_, motion, t, angles) => {
    expect(anglesAt(motion, t)).toEqual(angles);
  });

  it("moves smoothly: no step between samples at 10 Hz moves a joint more than 0.6 rad (no jumps)", () => {
    for (const motion of [waving, sitting, gestureBegun(stand, "animations/Stand/Gestures/Enthusiastic_4", 2)])
      for (let n = 0; n < 50; n++) {
        const [a, b] = [anglesAt(motion, n / 10), anglesAt(motion, (n + 1) / 10)];
        for (let j = 0; j < a.length; j++) expect(Math.abs(b[j]! - a[j]!)).toBeLessThan(0.6);
      }
  });
});
