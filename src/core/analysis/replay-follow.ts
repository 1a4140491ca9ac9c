// What the replay does when the recording it follows does something: the
// video is the clock, and the robot goes where it goes. Pure, so the page's
// following is tested without a browser.
import { REPLAY_SPEEDS } from "../trial/replay";

export type VideoEvent = "play" | "pause" | "seeked" | "ratechange";

export interface VideoNow {
  paused: boolean;
  /** Where the video is, on the trial's clock (ms from t0). */
  atMs: number;
  /** The video's playback rate. */
  rate: number;
}

export type ReplayMove =
  | { kind: "play"; fromMs: number; speed: number }
  | { kind: "stop"; reason?: string }
  /** Nothing to do: the robot already does what the video does. */
  | { kind: "none" };

export function followVideo(event: VideoEvent, video: VideoNow): ReplayMove {
  if (event === "pause") return { kind: "stop" };
  // Seeking or changing speed while paused moves nothing: the robot waits for the video to play.
  if (video.paused) return { kind: "none" };
  if (!(REPLAY_SPEEDS as readonly number[]).includes(video.rate))
    return {
      kind: "stop",
      reason: `The robot replays at ${REPLAY_SPEEDS.map((s) => `×${s}`).join(", ")} only; the video plays at ×${video.rate}.`,
    };
  return { kind: "play", fromMs: Math.max(0, video.atMs), speed: video.rate };
}
