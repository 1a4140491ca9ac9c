// The robot registry's rules, with no I/O: how a record names its secret,
// which registered robots can run a plugin, and the words a wizard reads when
// a robot is taken. The database and the runtime apply them.

/** Where a robot's SSH secret is read: an environment variable (a password) or a file (a private key). */
export type SecretReference = { kind: "env"; name: string } | { kind: "file"; path: string };

const ENV_NAME = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Reads "env:NAME" or "file:/absolute/path"; anything else is refused with the reason (a secret itself never fits). */
export function parseSecretReference(reference: string): SecretReference | { error: string } {
  const [kind, ...rest] = reference.split(":");
  const value = rest.join(":");
  if (kind === "env") {
    return ENV_NAME.test(value)
      ? { kind: "env", name: value }
      : { error: "must name an environment variable, e.g. env:NAO_A_SSH_PASSWORD" };
  }
  if (kind === "file") {
    return value.startsWith("/")
      ? { kind: "file", path: value }
      : { error: "must give the absolute path of a key file, e.g. file:/etc/hristudio/nao-a.key" };
  }
  return {
    error: "must be env:VARIABLE or file:/path (the secret itself is never stored; say where the server reads it)",
  };
}

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
 * The robot a new trial gets: the first (in the order given) that runs its
 * plugin and that no live trial holds, a robot of the plugin itself before one
 * that runs any plugin. When every such robot is held, the first of them: the
 * wizard sees which, and starting waits until its trial ends (`robotTaken`).
 * Null when none runs the plugin.
 */
export function chooseRobot<R extends RegisteredRobot>(
  available: R[],
  robotId: string,
  held: ReadonlySet<string>,
): R | null {
  const fitting = available.filter((r) => runsPlugin(r, robotId));
  const preferred = (list: R[]) => list.find((r) => r.pluginRobotId === robotId) ?? list[0] ?? null;
  return preferred(fitting.filter((r) => !held.has(r.id))) ?? preferred(fitting);
}

/** The refusal a wizard reads when the trial's robot is driven by another live trial. */
export function robotTaken(robotName: string, holder: string): string {
  return `The robot "${robotName}" is being driven by another live trial (${holder}). This trial can start once that one has ended.`;
}
