// The trial runtime's view of a robot: perform an action and report back
// through the same commands a wizard's reports would use. Transports (issue:
// robots) implement it; nothing else in the runtime knows which is live.
import type { Sensed } from "@/core/plugins/types";
export interface RobotRequest {
  actionId: string;
  actionType: string;
  parameters: Record<string, unknown>;
  /** When the wizard asked, on this process's clock: the link sends nothing older than its limit. */
  askedAt?: number;
}

export type RobotReport =
  | { kind: "dispatched"; actionId: string; detail?: Record<string, unknown> }
  | { kind: "completed"; actionId: string; detail?: Record<string, unknown> }
  | { kind: "failed"; actionId: string; reason: string }
  | { kind: "not_sent"; actionId: string; reason: string }
  | { kind: "unknown"; actionId: string; reason: string }
  | { kind: "timed_out"; actionId: string };

export interface CameraFrame {
  /** What sensor_msgs/CompressedImage says, e.g. "jpeg" or "rgb8; jpeg compressed bgr8". */
  format: string;
  /** The image's bytes, base64. */
  data: string;
}

export interface RobotLink {
  perform(request: RobotRequest, report: (r: RobotReport) => void): void;
  /** Stop everything now (emergency stop). */
  halt(): void;
  connected(): boolean;
  /** Robot state messages (the plugin's state topics) as they arrive; returns a function that stops them. */
  watchState(listener: (topic: string, message: unknown) => void): () => void;
  /** The robot's camera frames (the plugin's `camera`), base64, at its throttle; returns a function that stops them. */
  watchCamera(listener: (frame: CameraFrame) => void): () => void;
  /** Each event the plugin says the robot senses, as it happens (./robot-senses.ts); returns a function that stops them. */
  watchSenses(listener: (sensed: Sensed) => void): () => void;
  onConnection(listener: (connected: boolean, detail?: string) => void): void;
  /** An error or warning the robot's side reported (a refused subscription, a bridge's status frame): the trial logs it. */
  onProblem(listener: (problem: string) => void): void;
  close(): void;
}
