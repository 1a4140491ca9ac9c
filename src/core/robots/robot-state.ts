// What the simulated robot is doing: the simulator keeps it and publishes it
// as JSON on its own topic; the robot view page reads it from there. Declared
// once here, below both.

/**
 * The state's topic (ours, only on the simulator). Published on every change
 * and at least once a second, so a page that opens late draws the robot at once.
 */
export const ROBOT_STATE_TOPIC = "/hristudio/robot_state";

export interface RobotState {
  speaking: string | null;
  lastSaid: string | null;
  /** The last lines it began to say (at most SAID_KEPT, oldest first), so a page opened late or a glance away misses none. */
  said: Array<{ text: string; at: string }>;
  /** The sound file playing now (its name), and how long it lasts. */
  playing: { name: string; durationMs: number } | null;
  animation: string | null;
  gesture: string | null;
  posture: string;
  /** Motors on (woken up) or off (at rest). */
  awake: boolean;
  velocity: { linear: number; angular: number };
  /** Where a wheeled robot is on its map (m, rad), moved by /cmd_vel and navigation goals. */
  pose: { x: number; y: number; theta: number };
  headPitch: number;
  battery: number;
}

export const SAID_KEPT = 20;

/** The robot began to say `text` at `at`: kept among the last lines, the oldest let go. */
export function began(said: RobotState["said"], text: string, at: Date): RobotState["said"] {
  return [...said, { text, at: at.toISOString() }].slice(-SAID_KEPT);
}

export function initialState(): RobotState {
  return {
    speaking: null,
    lastSaid: null,
    said: [],
    playing: null,
    animation: null,
    gesture: null,
    posture: "stand",
    awake: true,
    velocity: { linear: 0, angular: 0 },
    pose: { x: 0, y: 0, theta: 0 },
    headPitch: 0,
    battery: 100,
  };
}

/**
 * Where a replay says what it is (ours, only on the simulator): published by
 * the runtime when a replay starts, ends, and about every second between, so
 * the robot page can say "replay of trial …" rather than pass it off as live.
 * It names the trial by id only: the simulator is open to anyone who can
 * reach it, and the robot page asks the server for the name, which tells only
 * members of the trial's study.
 */
export const REPLAY_TOPIC = "/hristudio/replay";

export interface ReplayAnnouncement {
  trialId: string;
  playing: boolean;
  speed: number;
  /** The trial's moment (ms from t0) the replay has reached. */
  positionMs: number;
  sent: number;
  total: number;
}
