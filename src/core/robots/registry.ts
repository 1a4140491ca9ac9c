// The robot registry's rules, with no I/O: which registered robots can run a
// plugin, and the words a wizard reads when a robot is taken. The database and
// the runtime apply them. How a record names its secret: secrets.ts.

export interface RegisteredRobot {
  id: string;
  name: string;
  /** The plugin's robotId; null: runs any plugin (a simulated robot, or the environment's robot). */
  pluginRobotId: string | null;
}

/** Whether the robot can run a trial whose version uses the plugin `robotId`. */
export function runsPlugin(robot: Pick<RegisteredRobot, "pluginRobotId">, robotId: string): boolean {
  return robot.pluginRobotId === null || robot.pluginRobotId === robotId;
}

/**
 * The robots a new trial may get, best first: those that run its plugin and
 * that no live trial holds, a robot of the plugin itself before one that runs
 * any plugin; then, the same way, the held ones. The runtime takes the first it
 * can claim; when every free one is claimed elsewhere, the first of them: the
 * wizard sees which, and starting waits until it is free (`robotTaken`).
 */
export function robotPreference<R extends RegisteredRobot>(
  available: R[],
  robotId: string,
  held: ReadonlySet<string>,
): R[] {
  const fitting = available.filter((r) => runsPlugin(r, robotId));
  const ordered = (list: R[]) => [
    ...list.filter((r) => r.pluginRobotId === robotId),
    ...list.filter((r) => r.pluginRobotId !== robotId),
  ];
  return [...ordered(fitting.filter((r) => !held.has(r.id))), ...ordered(fitting.filter((r) => held.has(r.id)))];
}

/** The refusal a wizard reads when the trial's robot is driven by another live trial. */
export function robotTaken(robotName: string, holder: string): string {
  return `The robot "${robotName}" is being driven by another live trial (${holder}). This trial can start once that one has ended.`;
}

/**
 * Who holds a robot besides its live trial: a trial open (not yet live) or starting in this runtime process,
 * a replay playing in it, or any of them in another runtime process (an advisory lock says only that it is held).
 */
export type RobotHolder = "open trial" | "starting trial" | "replay" | "elsewhere";

/** The refusal a wizard reads when the trial's robot is held by a start or a replay. */
export function robotClaimed(robotName: string, holder: RobotHolder): string {
  if (holder === "starting trial") return robotTaken(robotName, "a trial that is starting now");
  if (holder === "open trial") return robotTaken(robotName, "a trial open in this runtime");
  const by = holder === "replay" ? "a replay of a finished trial" : "a replay, or a trial open in another runtime";
  return `The robot "${robotName}" is being driven by ${by}. This trial can start once it is free.`;
}

/**
 * The refusal a replay gets when its simulated robot is busy. The trial that holds it is never named: it
 * may be another study's.
 */
export function replayBusy(robotName: string, holder: RobotHolder | "live trial"): string {
  const doing =
    holder === "replay"
      ? "playing another replay"
      : holder === "elsewhere"
        ? "busy with another trial or replay"
        : "running another trial";
  return `The simulated robot "${robotName}" is ${doing}; replay when it is free.`;
}
