// How a robot record names its SSH secret, with no I/O. A password is read
// from the runtime's environment, but only from variables meant for robots:
// the runtime sends it to whatever address the record gives, so a record that
// could name any variable could send the platform's own settings
// (BETTER_AUTH_SECRET, DATABASE_URL) to a host an administrator typed.

/** Where a robot's SSH secret is read: an environment variable (a password) or a file (a private key). */
export type SecretReference = { kind: "env"; name: string } | { kind: "file"; path: string };

/** Variables meant for robot passwords start with this; every other variable is the platform's own. */
export const ROBOT_SECRET_PREFIX = "HRI_ROBOT_SECRET_";

/** The password of the robot the environment names (README), a robot's secret by its meaning, as before records. */
const ENVIRONMENT_ROBOT_PASSWORD = "HRI_ROBOT_SSH_PASSWORD";

const ENV_NAME = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Whether a robot record may name this variable. */
export const isRobotSecret = (name: string) =>
  (name.startsWith(ROBOT_SECRET_PREFIX) && name.length > ROBOT_SECRET_PREFIX.length) ||
  name === ENVIRONMENT_ROBOT_PASSWORD;

/**
 * The robot variables of an environment, sorted, for the form to offer: names only, never values. Not the
 * environment robot's password: its record names it already (and the launcher sets it for the web app alone).
 */
export const robotSecretNames = (names: Iterable<string>) =>
  [...names].filter((n) => isRobotSecret(n) && n.startsWith(ROBOT_SECRET_PREFIX)).sort();

/**
 * Reads "env:HRI_ROBOT_SECRET_…" or "file:/absolute/path"; anything else is refused with the reason, which
 * reads after "The SSH secret …" (a secret itself never fits).
 */
export function parseSecretReference(reference: string): SecretReference | { error: string } {
  const [kind, ...rest] = reference.split(":");
  const value = rest.join(":");
  if (kind === "env") {
    if (!ENV_NAME.test(value))
      return { error: `must name an environment variable, e.g. env:${ROBOT_SECRET_PREFIX}NAO_A` };
    if (!isRobotSecret(value))
      return {
        error: `refers to ${value}, which is not a robot secret; name a variable starting ${ROBOT_SECRET_PREFIX}`,
      };
    return { kind: "env", name: value };
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
