// Transports are chosen here and nowhere else, from the plugin's `transport`.
// "simulated" is rosbridge to the built-in simulated robot.
import type { Plugin } from "../../core/plugins";
import { HttpTransport } from "./http";
import { RosbridgeTransport } from "./rosbridge";
import { RoutedTransport } from "./routed";
import { SshTransport, type SshOptions } from "./ssh";
import type { Transport } from "./transport";

export type { DispatchOutcome, Health, Transport } from "./transport";

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
  const kind = plugin.transport ?? "rosbridge";
  if (kind === "simulated") {
    if (!config.simulatorUrl) return { ok: false, reason: "the simulated robot is not running" };
    return { ok: true, transport: new RosbridgeTransport({ url: config.simulatorUrl }) };
  }
  if (kind === "rosbridge") {
    if (!config.rosbridgeUrl) return { ok: false, reason: `no rosbridge address configured for ${plugin.robotId}` };
    const rosbridge = new RosbridgeTransport({ url: config.rosbridgeUrl });
    return { ok: true, transport: new RoutedTransport(rosbridge, config.ssh ? new SshTransport(config.ssh) : null) };
  }
  if (kind === "ssh") {
    if (!config.ssh)
      return { ok: false, reason: `no SSH address configured for ${plugin.robotId} (HRI_ROBOT_SSH_HOST)` };
    return { ok: true, transport: new SshTransport(config.ssh) };
  }
  const base = config.httpBaseUrl ?? (typeof plugin.httpBaseUrl === "string" ? plugin.httpBaseUrl : undefined);
  if (!base) return { ok: false, reason: `no REST address configured for ${plugin.robotId}` };
  return { ok: true, transport: new HttpTransport({ baseUrl: base }) };
}
