// Transports are chosen here and nowhere else, from the plugin's `transport`.
// "simulated" is rosbridge to the built-in simulated robot. Whether a way to
// the robot is open is decided by the pure `unreachable`, the same function
// the designer's "can run" check uses.
import { isSshCommand, unreachable, type Plugin } from "../../core/plugins";
import { HttpTransport } from "./http";
import { channelsOf } from "./settings";
import { RosbridgeTransport } from "./rosbridge";
import { RoutedTransport } from "./routed";
import { SshTransport, type SshOptions } from "./ssh";
import type { Transport } from "./transport";

export type { DispatchOutcome, Health, Transport } from "./transport";
export { channelsOf, transportConfig } from "./settings";

export interface TransportConfig {
  /** The robot's rosbridge, e.g. ws://nao.local:9090. */
  rosbridgeUrl?: string;
  /** The simulated robot's rosbridge, started by the launcher. */
  simulatorUrl?: string;
  /** The robot's REST API, for plugins whose transport is "http" (default: the plugin's httpBaseUrl). */
  httpBaseUrl?: string;
  /** SSH to the robot, for the plugin's NAOqi (qicli) commands. */
  ssh?: SshOptions;
}

export type TransportChoice = { ok: true; transport: Transport } | { ok: false; reason: string };

export function transportFor(plugin: Plugin, config: TransportConfig): TransportChoice {
  const channels = channelsOf(config);
  const closed = unreachable(plugin, undefined, channels);
  if (closed) return { ok: false, reason: `${plugin.name} cannot be reached: ${closed}` };
  const kind = plugin.transport ?? "rosbridge";
  // No SSH connection to hold open for a robot that has no SSH commands.
  const ssh = config.ssh && (kind === "ssh" || plugin.actions.some(isSshCommand)) ? new SshTransport(config.ssh) : null;
  if (kind === "ssh") return { ok: true, transport: ssh! };
  const primary =
    kind === "http"
      ? new HttpTransport({ baseUrl: config.httpBaseUrl ?? String(plugin.httpBaseUrl) })
      : new RosbridgeTransport({ url: (kind === "simulated" ? config.simulatorUrl : config.rosbridgeUrl)!, plugin });
  return { ok: true, transport: new RoutedTransport(plugin, channels, primary, ssh) };
}
