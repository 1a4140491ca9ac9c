import { describe, expect, it } from "vitest";
import { followVideo, type ReplayMove, type VideoEvent, type VideoNow } from "./replay-follow";

const playing = (atMs: number, rate = 1): VideoNow => ({ paused: false, atMs, rate });
const paused = (atMs: number, rate = 1): VideoNow => ({ paused: true, atMs, rate });

describe("the replay following its recording", () => {
  it.each<[string, VideoEvent, VideoNow, ReplayMove]>([
    [
      "the video plays: the robot starts at its moment",
      "play",
      playing(12_000),
      { kind: "play", fromMs: 12_000, speed: 1 },
    ],
    ["the video plays at ×2: so does the robot", "play", playing(3_000, 2), { kind: "play", fromMs: 3_000, speed: 2 }],
    ["the video pauses: the robot stops", "pause", paused(15_000), { kind: "stop" }],
    [
      "the video is seeked while playing: the robot starts again there",
      "seeked",
      playing(40_000),
      { kind: "play", fromMs: 40_000, speed: 1 },
    ],
    ["the video is seeked while paused: the robot waits", "seeked", paused(40_000), { kind: "none" }],
    [
      "the video's speed changes while playing: the robot's too, from where it is",
      "ratechange",
      playing(8_000, 2),
      { kind: "play", fromMs: 8_000, speed: 2 },
    ],
    ["the video's speed changes while paused: nothing moves", "ratechange", paused(8_000, 2), { kind: "none" }],
    [
      "a recording that began before t0, still before it: the robot starts at t0",
      "play",
      playing(-2_500),
      { kind: "play", fromMs: 0, speed: 1 },
    ],
    [
      "a speed the robot does not replay at: it stops, and says why",
      "ratechange",
      playing(8_000, 1.5),
      { kind: "stop", reason: "The robot replays at ×0.5, ×1, ×2 only; the video plays at ×1.5." },
    ],
  ])("%s", (_name, event, video, move) => {
    expect(followVideo(event, video)).toEqual(move);
  });
});
