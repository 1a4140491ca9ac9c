// HRIStudio's named payload transforms ("payloadMapping": {"type": "transform",
// "transformFn": ...}). Most turn an action's parameters into the message to
// send; transformToRotation is a turn then a stop; extractRobotState reads the
// robot's odometry instead of sending. Only the names listed here run: an
// action naming another loads as unsupported (availability.ts).
// docs/plugins.md lists them with their messages.
import type { JsonObject, Plugin } from "./types";

type Parameters = Record<string, unknown>;

export type Transform =
  /** Parameters to the message sent. */
  | { kind: "message"; build: (parameters: Parameters) => JsonObject }
  /** A velocity held for a time, then a stop: needs the robot's top turning speed. */
  | { kind: "motion"; build: (parameters: Parameters, maxTurn: number) => Motion }
  /** Nothing is sent: the action reads one message of its topic. */
  | { kind: "reading"; read: (message: unknown) => JsonObject };

export interface Motion {
  message: JsonObject;
  stopAfterMs: number;
  stop: JsonObject;
}

const num = (value: unknown, fallback = 0) => (typeof value === "number" && Number.isFinite(value) ? value : fallback);
const vector = (x: number, y: number, z: number) => ({ x, y, z });
const twist = (linear: number, angular: number): JsonObject => ({
  linear: vector(linear, 0, 0),
  angular: vector(0, 0, angular),
});

/**
 * NAOqi's text-to-speech reads inline tags: \rspd=N\ sets the speaking rate and
 * \vct=N\ the pitch, both in percent. An emotion is a rate and pitch pair
 * ahead of the text, sent as std_msgs/String {data}. "neutral" or no emotion
 * sends the text alone, so say_with_emotion without an emotion equals say_text.
 */
const EMOTION_VOICE: Record<string, { rate: number; pitch: number }> = {
  happy: { rate: 110, pitch: 115 },
  sad: { rate: 85, pitch: 90 },
};

function transformToEmotionSpeech(parameters: Parameters): JsonObject {
  const text = typeof parameters.text === "string" ? parameters.text : "";
  const voice = typeof parameters.emotion === "string" ? EMOTION_VOICE[parameters.emotion] : undefined;
  return { data: voice ? `\\rspd=${voice.rate}\\\\vct=${voice.pitch}\\${text}` : text };
}

/** geometry_msgs/Twist from `linear` (m/s, forward) and `angular` (rad/s, counter-clockwise), as HRIStudio builds it. */
const transformToTwist = (parameters: Parameters) => twist(num(parameters.linear), num(parameters.angular));

/**
 * geometry_msgs/PoseStamped in the "map" frame from `x`, `y` (m) and `theta`
 * (rad, about z), as HRIStudio builds it, but stamped zero: ROS reads a zero
 * stamp as "the latest transform", where HRIStudio's sender clock would be
 * read by a robot whose clock differs as a pose from the past or the future.
 */
function transformToPoseStamped(parameters: Parameters): JsonObject {
  const theta = num(parameters.theta);
  return {
    header: { stamp: { sec: 0, nanosec: 0 }, frame_id: "map" },
    pose: {
      position: vector(num(parameters.x), num(parameters.y), 0),
      orientation: { x: 0, y: 0, z: Math.sin(theta / 2), w: Math.cos(theta / 2) },
    },
  };
}

/**
 * Turns by `angle` (rad, positive counter-clockwise) at `speed` (a fraction of
 * the robot's top turning speed): a Twist turning that way, and a stop once
 * the angle is covered. HRIStudio names the transform but never wrote it.
 */
function transformToRotation(parameters: Parameters, maxTurn: number): Motion {
  const angle = num(parameters.angle);
  const rate = Math.abs(num(parameters.speed, 0.5)) * maxTurn;
  const turning = rate > 0 && angle !== 0;
  return {
    message: twist(0, turning ? Math.sign(angle) * rate : 0),
    stopAfterMs: turning ? Math.round((Math.abs(angle) / rate) * 1000) : 0,
    stop: twist(0, 0),
  };
}

const field = (value: unknown, ...path: string[]): unknown =>
  path.reduce<unknown>(
    (at, key) => (at && typeof at === "object" ? (at as Record<string, unknown>)[key] : undefined),
    value,
  );

/**
 * The robot's state from a nav_msgs/Odometry message: where it is (x, y in
 * m, theta in rad from the orientation quaternion), how fast it goes (m/s,
 * rad/s), in which frame and when. HRIStudio names the transform but never
 * wrote it.
 */
function extractRobotState(message: unknown): JsonObject {
  const q = (key: string) => num(field(message, "pose", "pose", "orientation", key), key === "w" ? 1 : 0);
  const [x, y, z, w] = [q("x"), q("y"), q("z"), q("w")];
  const stamp = field(message, "header", "stamp");
  return {
    frame: String(field(message, "header", "frame_id") ?? ""),
    stamp: { sec: num(field(stamp, "sec")), nanosec: num(field(stamp, "nanosec")) },
    x: num(field(message, "pose", "pose", "position", "x")),
    y: num(field(message, "pose", "pose", "position", "y")),
    theta: Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)),
    linear: num(field(message, "twist", "twist", "linear", "x")),
    angular: num(field(message, "twist", "twist", "angular", "z")),
  };
}

export const TRANSFORMS: Record<string, Transform> = {
  transformToEmotionSpeech: { kind: "message", build: transformToEmotionSpeech },
  transformToTwist: { kind: "message", build: transformToTwist },
  transformToPoseStamped: { kind: "message", build: transformToPoseStamped },
  transformToRotation: { kind: "motion", build: transformToRotation },
  extractRobotState: { kind: "reading", read: extractRobotState },
};

export function transformOf(name: string): Transform | undefined {
  return Object.hasOwn(TRANSFORMS, name) ? TRANSFORMS[name] : undefined;
}

/**
 * The robot's top turning speed (rad/s), as its plugin declares it: the
 * `angular` maximum of its transformToTwist action. Null when it declares none.
 */
export function maxTurnOf(plugin: Pick<Plugin, "actions">): number | null {
  for (const action of plugin.actions) {
    const mapping = action.ros2 && "payloadMapping" in action.ros2 ? action.ros2.payloadMapping : null;
    if (mapping?.type !== "transform" || mapping.transformFn !== "transformToTwist") continue;
    const maximum = action.parameterSchema.properties.angular?.maximum;
    if (typeof maximum === "number" && maximum > 0) return maximum;
  }
  return null;
}
