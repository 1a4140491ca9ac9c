// How the simulated robot's body moves: each posture is a set of joint
// angles reached along a smooth (cosine-eased) path, and each gesture or
// animation is a short trajectory laid over the posture, so a joint plot of
// /joint_states shows what the robot did. Pure and timed in seconds of the
// joint-state clock, so the same commands give the same angles.

/** The joints published on /joint_states, in this order (NAO's names). */
export const BODY_JOINTS = ["HeadYaw", "HeadPitch", "LShoulderPitch", "RShoulderPitch"];

const POSTURES: Record<string, number[]> = {
  stand: [0, 0, 1.4, 1.4],
  sit: [0, 0.2, 1.0, 1.0],
  crouch: [0, 0.3, 1.2, 1.2],
  rest: [0, 0.5, 1.5, 1.5],
};

/** Seconds to reach a new posture. */
export const POSTURE_SECONDS = 1;
/** Seconds a gesture's trajectory lasts (the simulator's default animation time). */
export const GESTURE_SECONDS = 1.5;

export interface Motion {
  /** The angles the posture move starts from. */
  from: number[];
  posture: string;
  postureAt: number;
  gesture: string | null;
  gestureAt: number;
}

const anglesOf = (posture: string) => POSTURES[posture] ?? POSTURES.stand!;

/** A body resting in `posture`, nothing under way. */
export function still(posture: string): Motion {
  return { from: anglesOf(posture), posture, postureAt: 0, gesture: null, gestureAt: 0 };
}

export function postureChosen(motion: Motion, posture: string, at: number): Motion {
  return { ...motion, from: postureAngles(motion, at), posture, postureAt: at };
}

export function gestureBegun(motion: Motion, gesture: string, at: number): Motion {
  return { ...motion, gesture, gestureAt: at };
}

/** Every joint's angle (rad, BODY_JOINTS order) at `t` seconds. */
export function anglesAt(motion: Motion, t: number): number[] {
  const offset = gestureOffset(motion, t);
  return postureAngles(motion, t).map((angle, i) => round(angle + offset[i]!));
}

function postureAngles(motion: Motion, t: number): number[] {
  const to = anglesOf(motion.posture);
  const k = ease((t - motion.postureAt) / POSTURE_SECONDS);
  return motion.from.map((from, i) => from + (to[i]! - from) * k);
}

function gestureOffset(motion: Motion, t: number): number[] {
  const p = (t - motion.gestureAt) / GESTURE_SECONDS;
  if (!motion.gesture || p < 0 || p >= 1) return [0, 0, 0, 0];
  // Up and back down once over the gesture, so it ends where the posture is.
  const up = Math.sin(Math.PI * p);
  const swing = (times: number) => Math.sin(2 * Math.PI * times * p);
  const name = motion.gesture.toLowerCase();
  if (name.includes("wave") || name.includes("hey")) return [0, 0, 0, -2 * up + 0.3 * up * swing(3)];
  if (name.includes("nod")) return [0, 0.3 * up * swing(2), 0, 0];
  if (name.includes("shake")) return [0.5 * up * swing(2), 0, 0, 0];
  if (name.includes("look_down")) return [0, 0.4 * up, 0, 0];
  if (name.includes("bow")) return [0, 0.5 * up, 0.2 * up, 0.2 * up];
  // Any other animation: both arms rise and the head turns a little.
  return [0.2 * up * swing(1), 0, -up, -up];
}

const ease = (k: number) => (k <= 0 ? 0 : k >= 1 ? 1 : (1 - Math.cos(Math.PI * k)) / 2);
/** Micro-radians: whole numbers on the wire, the same on every machine. */
const round = (angle: number) => Math.round(angle * 1e6) / 1e6;
