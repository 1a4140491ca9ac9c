// Whether this server can carry an action to its robot: the way (channel)
// the action travels, and whether the server's settings give that way an
// address. The designer's "can run" and the runtime's dispatch both ask
// here, so what the designer calls runnable is what the runtime runs.
import type { PluginAction, TransportKind } from "./types";

export type Channel = "rosbridge" | "simulator" | "ssh" | "http";

/** The ways to the robot this server's settings give an address for (not whether the robot answers now). */
export type Channels = Record<Channel, boolean>;

/** What of a plugin decides its ways: its transport, and the robot's address an HTTP plugin may name. */
export interface Reachable {
  transport?: TransportKind;
  httpBaseUrl?: unknown;
}

/** A NAOqi command the plugin runs over SSH, whatever its plugin's transport. */
export const isSshCommand = (action: PluginAction) =>
  !!action.ros2 && "payloadMapping" in action.ros2 && action.ros2.payloadMapping?.type === "ssh";

/** How the action reaches the robot; without an action, how the plugin's robot is reached at all. */
export function channelOf(plugin: Reachable, action?: PluginAction): Channel {
  if (action && isSshCommand(action)) return "ssh";
  const kind = plugin.transport ?? "rosbridge";
  return kind === "simulated" ? "simulator" : kind;
}

const NEEDS: Record<Channel, string> = {
  rosbridge:
    "the robot's rosbridge, and this server has no address for it: set HRI_ROSBRIDGE_URL (see docs/robot-setup.md)",
  simulator:
    "the simulated robot, which this server is not running (npm start runs it when HRI_ROSBRIDGE_URL is not set)",
  ssh: "SSH to the robot, and this server has no SSH address for it: set HRI_ROBOT_SSH_HOST (see docs/robot-setup.md)",
  http: "the robot's REST API, and neither its plugin nor this server gives the address: set HRI_ROBOT_HTTP_URL",
};

/**
 * Why this server cannot carry the action (without one: any of the plugin's
 * actions) to the robot, in words that follow "cannot run: "; null when it
 * can. The robot's own way must be open first: the runtime reaches a robot
 * through it, SSH commands included.
 */
export function unreachable(plugin: Reachable, action: PluginAction | undefined, channels: Channels): string | null {
  // An HTTP plugin may name its robot's address itself.
  const open = (channel: Channel) =>
    channels[channel] || (channel === "http" && typeof plugin.httpBaseUrl === "string");
  const closed = [channelOf(plugin), channelOf(plugin, action)].find((channel) => !open(channel));
  return closed ? `it needs ${NEEDS[closed]}` : null;
}
