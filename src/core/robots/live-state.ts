// What the wizard sees of the robot while a trial runs: whether it is
// speaking (and what), its gesture, its posture and its battery. Folded from
// the state topics the runtime already receives: any sensor_msgs/BatteryState
// (every plugin's /battery), and the simulated robot's own state report
// (ROBOT_STATE_TOPIC). A real robot that reports no speech or posture leaves
// those unknown (null), never guessed.
import { initialState, ROBOT_STATE_TOPIC, type RobotState } from "./robot-state";

export interface LiveRobotState {
  speaking: string | null;
  gesture: string | null;
  posture: string | null;
  /** Percent, 0–100; null until the robot reports it. */
  battery: number | null;
}

export const UNKNOWN_STATE: LiveRobotState = { speaking: null, gesture: null, posture: null, battery: null };

/** Below this the wizard is warned: a NAO at 20 % has minutes of walking left, not a session. */
export const LOW_BATTERY_PERCENT = 20;

export function batteryLow(state: LiveRobotState): boolean {
  return state.battery !== null && state.battery < LOW_BATTERY_PERCENT;
}

/**
 * What the wizard is told before a trial starts when the robot is not in the
 * posture it starts in: a posture carries over from the last trial (or from
 * anyone who moved it), and a protocol that assumes a standing robot would
 * otherwise begin from a sitting one unannounced. Null when it is in its
 * starting posture or does not report one.
 */
export function carriedPosture(name: string | undefined, state: LiveRobotState | null): string | null {
  const starting = initialState().posture;
  if (!state?.posture || state.posture === starting) return null;
  return `${name ?? "The robot"} is in the posture "${state.posture}", as the last trial or session left it; it starts in "${starting}". Set its posture before the participant arrives if the protocol expects "${starting}".`;
}

/** The battery's charge in percent from a sensor_msgs/BatteryState (`percentage` is 0–1, NaN when unknown). */
export function batteryPercent(message: unknown): number | null {
  const m = message as { percentage?: unknown; power_supply_status?: unknown } | null;
  if (typeof m?.percentage !== "number" || typeof m.power_supply_status !== "number") return null;
  if (!Number.isFinite(m.percentage)) return null;
  return Math.round(Math.min(1, Math.max(0, m.percentage)) * 1000) / 10;
}

/** The state after one message of a state topic; the same object when nothing the wizard sees changed. */
export function foldLiveState(state: LiveRobotState, topic: string, message: unknown): LiveRobotState {
  const next = { ...state };
  if (topic === ROBOT_STATE_TOPIC) {
    const report = parseReport(message);
    if (!report) return state;
    next.speaking = report.speaking;
    next.gesture = report.gesture ?? report.animation;
    next.posture = report.posture;
    next.battery = Math.round(report.battery * 10) / 10;
  } else {
    const battery = batteryPercent(message);
    if (battery === null) return state;
    next.battery = battery;
  }
  const same = (Object.keys(next) as (keyof LiveRobotState)[]).every((k) => next[k] === state[k]);
  return same ? state : next;
}

function parseReport(message: unknown): RobotState | null {
  const data = (message as { data?: unknown } | null)?.data;
  if (typeof data !== "string") return null;
  try {
    const parsed = JSON.parse(data) as Partial<RobotState>;
    return typeof parsed.posture === "string" && typeof parsed.battery === "number" ? (parsed as RobotState) : null;
  } catch {
    return null;
  }
}
