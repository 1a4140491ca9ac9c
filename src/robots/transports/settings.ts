// The server's robot settings (HRI_ROSBRIDGE_URL, HRI_ROBOT_SSH_*,
// HRI_ROBOT_HTTP_URL) read the same way for both servers: the runtime reaches
// the robot with them, the web app tells the designer which ways they open.
// Types only: the web app imports this without the transports themselves.
import type { Channels } from "../../core/plugins";
import type { Config } from "../../store/config";
import type { TransportConfig } from "./index";

export function transportConfig(config: Config): TransportConfig {
  return {
    rosbridgeUrl: config.HRI_ROSBRIDGE_URL,
    // The launcher points HRI_ROSBRIDGE_URL at the simulated robot when no real one is set.
    simulatorUrl: config.HRI_ROSBRIDGE_URL,
    httpBaseUrl: config.HRI_ROBOT_HTTP_URL,
    ssh: config.HRI_ROBOT_SSH_HOST
      ? {
          host: config.HRI_ROBOT_SSH_HOST,
          port: config.HRI_ROBOT_SSH_PORT,
          username: config.HRI_ROBOT_SSH_USER,
          password: config.HRI_ROBOT_SSH_PASSWORD,
          privateKeyFile: config.HRI_ROBOT_SSH_KEY_FILE,
        }
      : undefined,
  };
}

/** The ways to a robot these settings give an address for. */
export function channelsOf(config: TransportConfig): Channels {
  return {
    rosbridge: Boolean(config.rosbridgeUrl),
    simulator: Boolean(config.simulatorUrl),
    ssh: Boolean(config.ssh),
    http: Boolean(config.httpBaseUrl),
  };
}
